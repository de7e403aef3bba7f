// SPDX-License-Identifier: MIT
// The contact report's named values (semantics §10): who a contact entity
// touched and stands on, by name, and the scene's pairs. The core marks
// what a step wrote (Body::touching, Body::standing_on) and logs pairs by
// index; here those become names, and the edits that write them.
#pragma once
#include <libguile.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "body.hpp"
#include "plist.hpp"

namespace ds::guile {

using IndexPair = std::pair<uint32_t, uint32_t>;

// Which report keys a call writes on its contact entities.
enum ReportKeys : uint8_t {
    kReportsTouching = 1u << 0,  // push-apart ran (bulk, or a frame)
    kReportsStanding = 1u << 1,  // a frame: detect-on-solid ran where it applies
};

// A contact body's partner and the side it met it on (a kSide bit).
struct Touch {
    uint32_t body, other;
    uint8_t side;
    bool operator<(const Touch& t) const { return body != t.body ? body < t.body : other < t.other; }
};

// What a frame's (or a bulk push-apart's) pair log says, by index.
struct ContactIndex {
    std::vector<Touch> touching;      // by (contact body, other), each once
    std::vector<IndexPair> pairs;     // (earlier, later) with a contact body or a sensor, each once, in order resolved
    std::vector<uint8_t> pair_sides;  // by pairs: the earlier body's side
    std::vector<IndexPair> seen;      // scratch: the pairs sorted, each once
    std::vector<uint8_t> used;        // scratch: by seen, taken already

    // From the pairs resolved (earlier body first) over `bodies`, and the
    // side each pair's first body met the second on (`sides`, pair for
    // pair): a pair a frame's sub-frames resolved again keeps its first
    // side, as it keeps its first place.
    void gather(std::span<const IndexPair> log, std::span<const uint8_t> sides, std::span<const Body> bodies);
    void clear() {
        touching.clear();
        pairs.clear();
        pair_sides.clear();
    }
};

// An entity's name in a report: its #:id unless absent or #f, else its
// 0-based position in the list.
SCM entity_name(SCM entity, size_t index);
// The names of a list's entities, for many look-ups: a Scheme vector that
// holds the entities and each name once it was asked for (name_at). With
// `ids` (the bodies' #:id tags, identity_tag), the names of entities without
// an id or with a symbol or immediate one are known without reading their
// plists (the tag is 0, or the id's own bits).
SCM entity_names(SCM entities, std::span<const int64_t> ids = {});
// The name of entity k of entity_names' vector.
SCM name_at(SCM names, size_t k);

// The #:touching value of body i: the names of its partners, in list order;
// `with_sides` (#:contacts? 'sides), each as (name . side).
SCM touching_names(const ContactIndex& index, size_t i, SCM names, bool with_sides);
// The #:standing-on value of a body (its supporter's name, or #f).
SCM standing_name(const Body& b, SCM names);

// Completes a contact entity's edits: fills in the report values
// (`touching`, `standing`; SCM_UNDEFINED where the call does not write that
// key), drops an edit whose value is equal? to the plist's, and adds one for
// a key the plist holds with another value. Room for two more in `edits`.
size_t report_edits(SCM entity, SCM touching, SCM standing, Edit* edits, size_t n);
// The same, given the values the plist holds (`old_touching`, `old_standing`;
// SCM_UNDEFINED when absent) instead of reading them from it: a cached
// entity's report keys may sit at the far end of a long plist.
size_t report_edits(SCM old_touching, SCM old_standing, SCM touching, SCM standing, Edit* edits, size_t n);

// The scene's pairs as ((name-a . name-b) …) against `names`.
SCM pair_names(std::span<const IndexPair> pairs, SCM names);
// The sides of the scene's pairs (pair_sides), a bytevector of side numbers
// (the kSide bit's index: 0 left, 1 right, 2 up, 3 down): one allocation
// a frame, whoever asks for the sides (scene-contact-sides) names them.
SCM side_codes(std::span<const uint8_t> sides);

}  // namespace ds::guile
