// SPDX-License-Identifier: MIT
// Ground detection (semantics §4, detect-on-solid): whether a tile or a solid
// body holds a body up, with the tolerance *on-solid-tolerance*
// (constants.hpp), and the resting contacts beyond the seed.
#pragma once
#include <cstddef>
#include <span>

#include "body.hpp"
#include "steps.hpp"
#include "tile_grid.hpp"
#include "export.hpp"

namespace ds {

// Whether a solid cell lies in row ⌊(y+h)/th⌋ under any column the box spans
// (or a one-way one, §9), or a shape there holds the feet (§12).
DOWNSTROKE_API bool tile_supports(const Body& b, const TileGrid& grid);
// Whether `other` holds `b` up: solid, not a ghost, overlapping horizontally,
// its top within the tolerance of b's feet and moving at nearly b's speed.
// (Identity — "other is not b itself" — is the caller's business.)
DOWNSTROKE_API bool entity_supports(const Body& b, const Body& other);

// Resting contact (beyond the seed; FrameOptions::resting_contacts): a still
// body (vy = 0) whose feet are exactly on the top of a solid whole tile, or on the
// top of a still solid body overlapping it horizontally. Such a body skips
// gravity, so a stack at rest stays exactly where it is.
DOWNSTROKE_API bool rests_on_tile(const Body& b, const TileGrid& grid);

// detect_on_solid returns whether it applied (false: no #:gravity?, or it
// skips 'on-solid), as the tile steps return whether they looked at the map.
// Sets on_ground from the tiles and from the frame-start scene. self_slot is
// b's own index in `scene` (or -1); bodies with b's nonzero id are skipped too.
// Needs #:gravity?; skipped by 'on-solid (semantics §4).
DOWNSTROKE_API bool detect_on_solid(Body& b, std::span<const Body> scene, std::ptrdiff_t self_slot,
                     const TileGrid* grid);

// The contact report's #:standing-on (semantics §10): the first body of
// `scene`, in its order, that holds b up by detect_on_solid's entity rule
// (tiles aside), or -1. For a body that detects ground (Body::detects_ground).
DOWNSTROKE_API std::ptrdiff_t first_supporter(const Body& b, std::span<const Body> scene, std::ptrdiff_t self_slot);

}  // namespace ds
