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

// What a frame's (or a bulk push-apart's) pair log says, by index.
struct ContactIndex {
    std::vector<IndexPair> touching;  // (contact body, other), sorted, each once
    std::vector<IndexPair> pairs;     // (earlier, later) with a contact body or a sensor, each once, in order resolved
    std::vector<IndexPair> seen;      // scratch: the pairs sorted, each once
    std::vector<uint8_t> used;        // scratch: by seen, taken already

    // From the pairs resolved (earlier body first) over `bodies`.
    void gather(std::span<const IndexPair> log, std::span<const Body> bodies);
    void clear() {
        touching.clear();
        pairs.clear();
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

// The #:touching value of body i: the names of its partners, in list order.
SCM touching_names(const ContactIndex& index, size_t i, SCM names);
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

}  // namespace ds::guile
