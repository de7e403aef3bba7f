// SPDX-License-Identifier: MIT
// Bodies against the solid cells of a tile grid: the per-axis snap-out
// (semantics §4). Ground detection is in ground.hpp.
#pragma once
#include <span>

#include "body.hpp"
#include "steps.hpp"
#include "tile_grid.hpp"
#include "export.hpp"

namespace ds {

enum class CollisionMode : uint8_t {
    Swept,     // also tests every cell the leading edge crossed: nothing tunnels
    Discrete,  // the seed's rule: only the cells the box overlaps after the move
};

// What push-apart does about solid cells (semantics §4).
enum class PushRule : uint8_t {
    Clipped,  // the default: a push stops at a solid cell, and a body in one is put out
    Seed,     // the seed's: pushes ignore the map
};

// Snap out of solid cells along x after apply-velocity-x. No-op without a
// grid, when vx = 0, or when the body skips 'tile-collisions-x.
// In a sub-frame, swept mode covers the sub-frame's move (vx·h) (semantics §4).
DOWNSTROKE_API bool resolve_tile_collisions_x(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s = {});
// The same along y, after apply-velocity-y ('tile-collisions-y) (semantics §4).
DOWNSTROKE_API bool resolve_tile_collisions_y(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s = {});
// In a grid with shaped cells (semantics §12) the x step also lifts a body
// up a floor ramp (or down under a ceiling ramp) it walks into, and the y
// step lands on a shape's surface and keeps a body that walks down a ramp
// on it (snapping down; not for a carried move, SubStep::carried).

// Whether the body's box overlaps a solid part of the grid: a whole solid
// cell, or a solid shape (one-way cells and shapes do not count).
DOWNSTROKE_API bool overlaps_solid(const Body& b, const TileGrid& grid);

}  // namespace ds
