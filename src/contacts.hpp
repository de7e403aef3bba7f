// Entity against entity: the overlap test and the sequential push-apart pass.
#pragma once
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "body.hpp"

namespace ds {

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
bool collision_eligible(const Body& a, const Body& b);

// Pushes one eligible pair apart (a is the earlier in list order). With
// resting contacts, a body that rested at the start of the (sub-)frame holds
// up one whose centre is above its own, as an immovable body would: the
// other lands on it (semantics §4's immovable rule, first case).
void resolve_pair(Body& a, Body& b, bool a_rests = false, bool b_rests = false);

// An overlapping pair of the pass (a the earlier): whether it meets, and if
// so what happens — categories that do not meet leave it alone; a sensor
// and a body it senses only meet (the pair is noted), two sensors do not;
// otherwise resolve_pair. Returns whether the pair met (§10, §13).
inline bool meet(Body& a, Body& b, bool a_rests, bool b_rests) {
    if (!categories_meet(a, b)) return false;
    if (a.sensor | b.sensor) return !(a.sensor & b.sensor);
    resolve_pair(a, b, a_rests, b_rests);
    return true;
}

// The pairs push-apart resolved, as body indices (the earlier first), in the
// order resolved: what the debug overlay draws. Nothing is noted unless the
// Frame is given a log (Frame::note_pairs), so a frame pays one test per pair.
using PairLog = std::vector<std::pair<uint32_t, uint32_t>>;
inline void note_pushed(PairLog* log, size_t a, size_t b) {
    if (log) log->emplace_back(static_cast<uint32_t>(a), static_cast<uint32_t>(b));
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
void resolve_entity_collisions(std::span<Body> bodies);
void resolve_entity_collisions_by(std::span<Body> bodies, PairMethod method,
                                  std::span<const uint8_t> resting = {});

}  // namespace ds
