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
// newly entered downwards has its top at or below the feet, §9); a shaped
// cell stops it as a whole cell would (its shape is not consulted yet).
Num clipped_push(const Body& b, bool along_x, Num d, const TileGrid& grid);

// Puts a body that overlaps whole solid cells out of them by the shortest
// of the four axis moves to a place that overlaps none (each direction tries
// the places with the body's leading face on a cell edge, nearest first; the
// grid's edge ends the search, beyond it nothing is solid); ties go up,
// left, right, down in that order. The velocity along that axis is
// zeroed when it pointed back into the cells. One-way and shaped cells are
// not counted (a body stands in a ramp's cell). Returns whether it moved.
bool put_out_of_solids(Body& b, const TileGrid& grid);

}  // namespace ds
