// SPDX-License-Identifier: MIT
// Push-apart's tile rule (semantics §4, "push-apart never leaves a body in a
// solid"): a push is cut where the body meets a solid cell, and a body that
// starts a (sub-)frame inside one is put out first.
#pragma once
#include "../body.hpp"
#include "../tile_grid.hpp"

namespace ds {

// How far of a push `d` (px, along x or y) a body can go before its leading
// face meets the first solid cell it would enter, in the rows (moving along
// x) or columns (along y) it spans: d itself when nothing stops it, else the
// distance to that cell's near face (0 when flush). Cells the body already
// overlaps do not stop it; a one-way cell stops only a move down (a cell
// newly entered downwards has its top at or below the feet, §9). A shaped
// cell stops it by its solid (§12) where the tile steps would: the feet on
// its surface, the head on its underside, the leading face on its near
// side, or the box's corner on a slant that faces the move.
Num clipped_push(const Body& b, bool along_x, Num d, const TileGrid& grid);

// Puts a body that overlaps a whole solid cell or a solid shape (not a
// one-way one) out by the shortest of the four axis moves to a place that
// overlaps none: each direction goes from place to place, each the nearest
// where the body has left every solid it overlapped at the last (a cell by
// its far edge; a shape by its surface moving up, its underside moving down,
// its box's side along x); beyond the grid nothing is solid. The four are
// searched side by side, nearest first, so the cost is the shortest way's
// cells times the body's, whatever the map's size. Ties go up, left, right,
// down in that order. The velocity along that axis is zeroed when it
// pointed back into the solids. Returns whether it moved.
bool put_out_of_solids(Body& b, const TileGrid& grid);

}  // namespace ds
