// SPDX-License-Identifier: MIT
// Platforms that carry their riders (semantics §11): a moving carrier moves
// the bodies that stood on it when the (sub-)frame began by its own
// displacement, and the bodies it squeezes against solid cells are crushed.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "body.hpp"
#include "frame_options.hpp"
#include "tile_grid.hpp"

namespace ds {

// #:carries? on a solid, immovable, non-ghost body.
inline bool is_carrier(const Body& b) { return b.carries && b.immovable && b.collides(); }
// Movable, solid, not a ghost: a carrier can push it, so it can be crushed.
inline bool is_crushable(const Body& b) { return !b.immovable && b.collides(); }
// A crushable body that does not skip 'carry.
inline bool may_ride(const Body& b) { return is_crushable(b) && !b.skips(kSkipCarry); }

// What a frame's carry keeps between its halves: the riders taken this
// (sub-)frame and the bodies a moving carrier overlapped before push-apart.
struct CarryScratch {
    std::vector<uint8_t> ridden;  // by body
    std::vector<size_t> in_way;   // body indices, in list order
};

// The frame starts with no body crushed: #:crushed? #t becomes #f on every
// crushable body of `members` (the first sub-frame only).
void clear_crushed(std::span<Body> bodies, std::span<const size_t> members);

// The carry step over `bodies` (after the per-entity steps), `start` being
// the same bodies when the (sub-)frame began. `carriers` and `members` are
// body indices in list order (the carriers among the members). A rider is
// moved along x, then y, by its carrier's displacement, each resolved
// against the solid cells as a tile step with that motion would; one whose
// upward carry a solid cell stops is crushed. Writes only x, y and crushed (semantics §11).
void carry_riders(std::span<Body> bodies, std::span<const Body> start,
                  std::span<const size_t> carriers, std::span<const size_t> members,
                  const TileGrid* grid, CollisionMode mode, CarryScratch& scratch);

// Before push-apart: notes the crushable members a moving carrier (not
// one-way) overlaps, the bodies it is about to push.
void note_in_way(std::span<const Body> bodies, std::span<const Body> start,
                 std::span<const size_t> carriers, std::span<const size_t> members,
                 CarryScratch& scratch);
// After push-apart: those of them now overlapping a solid cell are crushed;
// with `walls_cut` (the default push rule, §4, where a solid cell cuts the
// push short) so are those still overlapping a carrier (not one-way).
void crush_in_way(std::span<Body> bodies, std::span<const size_t> carriers, const TileGrid* grid,
                  bool walls_cut, const CarryScratch& scratch);

}  // namespace ds
