// Bodies against the solid cells of a tile grid: the per-axis snap-out
// (semantics §4). Ground detection is in ground.hpp.
#pragma once
#include <span>

#include "body.hpp"
#include "steps.hpp"
#include "tile_grid.hpp"

namespace ds {

enum class CollisionMode : uint8_t {
    Swept,     // also tests every cell the leading edge crossed: nothing tunnels
    Discrete,  // the seed's rule: only the cells the box overlaps after the move
};

// Snap out of solid cells along x after apply-velocity-x. No-op without a
// grid, when vx = 0, or when the body skips 'tile-collisions-x.
// In a sub-frame, swept mode covers the sub-frame's move (vx·h).
bool resolve_tile_collisions_x(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s = {});
// The same along y, after apply-velocity-y ('tile-collisions-y).
bool resolve_tile_collisions_y(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s = {});

}  // namespace ds
