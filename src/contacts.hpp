// SPDX-License-Identifier: MIT
// Entity against entity: the overlap test and the sequential push-apart pass.
#pragma once
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "body.hpp"
#include "extent.hpp"
#include "export.hpp"

namespace ds {

class TileGrid;

// Strict overlap of [x1, x1+w1) × [y1, y1+h1) and [x2, x2+w2) × [y2, y2+h2):
// touching edges do not overlap. Inline: the grid pass asks once per candidate.
inline bool aabb_overlap(double x1, double y1, double w1, double h1, double x2, double y2,
                         double w2, double h2) {
    return x1 < x2 + w2 && x2 < x1 + w1 && y1 < y2 + h2 && y2 < y1 + h1;
}
inline bool aabb_overlap(const Body& a, const Body& b) {
    return aabb_overlap(a.x.v, a.y.v, a.w.v, a.h.v, b.x.v, b.y.v, b.w.v, b.h.v);
}

// Whether a pair takes part in push-apart: both solid, neither a sensor nor
// skipping 'entity-collisions, their categories meet, and the boxes overlap
// strictly.
DOWNSTROKE_API bool collision_eligible(const Body& a, const Body& b);

// Pushes one eligible pair apart (a is the earlier in list order). With
// resting contacts, a body that rested at the start of the (sub-)frame holds
// up one whose centre is above its own, as an immovable body would: the
// other lands on it (semantics §4's immovable rule, first case).
// Returns the side of a that met b (a kSide bit, semantics §10): the axis
// and direction it was pushed on, or for a pair nothing moved (two
// immovable bodies, a one-way body passed through) the axis their overlap
// began on last (sensed_side).
// `walls`: under the seed's push rule none; under the default (PushRule::
// Clipped, §4) the map, whose solid cells cut every push short.
DOWNSTROKE_API uint8_t resolve_pair(Body& a, Body& b, bool a_rests = false, bool b_rests = false,
                                    const TileGrid* walls = nullptr);

// The side of a that met b when neither moves (a sensor's pair): the axis
// their overlap began on last, judged from their relative speed (x when
// ox·|Δvy| < oy·|Δvx|), else the narrower overlap's; facing b's centre, and
// on a tie as if a were pushed the negative way (right along x, down along y).
DOWNSTROKE_API uint8_t sensed_side(const Body& a, const Body& b);

// A side seen from the other body: left and right, up and down swapped.
constexpr uint8_t opposite_side(uint8_t side) {
    return static_cast<uint8_t>(((side & (kSideLeft | kSideUp)) << 1) | ((side & (kSideRight | kSideDown)) >> 1));
}

// An overlapping pair of the pass (a the earlier): whether it meets, and if
// so what happens — categories that do not meet leave it alone; a sensor
// and a body it senses only meet (the pair is noted), two sensors do not;
// otherwise resolve_pair. Returns 0 when the pair did not meet, else the
// side of a that met b (§10, §13).
inline uint8_t meet(Body& a, Body& b, bool a_rests, bool b_rests, const TileGrid* walls = nullptr) {
    if (!categories_meet(a, b)) return 0;
    if (a.sensor | b.sensor) return (a.sensor & b.sensor) ? 0 : sensed_side(a, b);
    return resolve_pair(a, b, a_rests, b_rests, walls);
}

// The pairs push-apart resolved, as body indices (the earlier first), in the
// order resolved: what the debug overlay draws. Nothing is noted unless the
// Frame is given a log (Frame::note_pairs), so a frame pays one test per pair.
using PairLog = std::vector<std::pair<uint32_t, uint32_t>>;
// Beside a PairLog, from where its owner began noting (ContactScratch::sides):
// the side of each pair's first body that met the second (a kSide bit), so
// that #:touching and the scene's contacts can say it (§10). A byte a pair,
// written only when pairs are noted at all.
using SideLog = std::vector<uint8_t>;
inline void note_pushed(PairLog* log, SideLog* sides, size_t a, size_t b, uint8_t side) {
    if (!log) return;
    log->emplace_back(static_cast<uint32_t>(a), static_cast<uint32_t>(b));
    if (sides) sides->push_back(side);
}
// After a pair met, the rooms by body (when a Frame records them for its
// resting groups, settle.hpp) take both boxes: a body pushed away and back
// within the pass still met what lay on the way.
inline void note_rooms(Extent* rooms, size_t a, const Body& first, size_t b, const Body& second) {
    if (!rooms) return;
    rooms[a].add(first);
    rooms[b].add(second);
}

// Push-apart writes every contact body's #:touching (semantics §10), named
// by the bindings from the pairs it resolved: marks it written.
inline void mark_touching(std::span<Body> bodies) {
    for (Body& b : bodies)
        if (b.contacts) b.touching = 0;
}

// How resolve_entity_collisions finds pairs. Both give identical results;
// Auto uses the grid from a few dozen solid bodies on.
enum class PairMethod { Auto, AllPairs, Grid };

// One pass over the pairs (i, j), i < j, in list order; each pair sees what
// earlier pairs produced. `resting` (empty, or one flag per body) marks the
// bodies that rested. Allocates its scratch per call and notes no pairs; a
// Frame keeps its own scratch (detail/contact_scratch.hpp).
DOWNSTROKE_API void resolve_entity_collisions(std::span<Body> bodies);
DOWNSTROKE_API void resolve_entity_collisions_by(std::span<Body> bodies, PairMethod method,
                                  std::span<const uint8_t> resting = {});

}  // namespace ds
