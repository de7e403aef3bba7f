// SPDX-License-Identifier: MIT
// Push-apart with scratch the caller keeps (a Frame, the Scheme bindings):
// the core's machinery behind resolve_entity_collisions (contacts.hpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "../contacts.hpp"
#include "broadphase.hpp"

namespace ds {

// What push-apart keeps between calls so that a warm caller does not
// allocate: the colliding bodies' indices and the grid pass. A Frame owns
// one; `log`, when set, receives every pair resolved (the debug overlay),
// and `sides`, when set too, the side of each one's first body: the caller
// clears it where it begins noting (the log may hold earlier pairs, the
// overlay's) and keeps it.
struct ContactScratch {
    std::vector<size_t> members;
    PairSweep sweep;
    PairLog* log = nullptr;
    SideLog* sides = nullptr;
    // The map whose solid cells cut pushes short (PushRule::Clipped, §4), or
    // none under the seed's rule.
    const TileGrid* walls = nullptr;
    // By body, when set: each body's room, taking its box after every pair
    // it meets (note_rooms). A Frame sets it while resting groups may form
    // or sleep.
    Extent* rooms = nullptr;
};

// One pass over the pairs (i, j), i < j, in list order; each pair sees what
// earlier pairs produced.
// `resting` (empty, or one flag per body) marks the bodies that rested.
void resolve_entity_collisions(ContactScratch& scratch, std::span<Body> bodies,
                               PairMethod method = PairMethod::Auto,
                               std::span<const uint8_t> resting = {});
// The same for a caller that already knows which bodies collide (Body::collides),
// in list order: no sweep over the others (scratch.members is not used).
void resolve_entity_collisions_among(ContactScratch& scratch, std::span<Body> bodies,
                                     std::span<const size_t> members,
                                     std::span<const uint8_t> resting);

}  // namespace ds
