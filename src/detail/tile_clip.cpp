// SPDX-License-Identifier: MIT
#include "tile_clip.hpp"

#include <algorithm>
#include <cmath>

namespace ds {

namespace {

// Stops a push: solid and shaped cells always, one-way cells a move down.
bool stops(uint8_t cell, bool down) {
    return cell == kSolidCell || cell == kShapedCell || (down && cell == kOneWayCell);
}

}  // namespace

Num clipped_push(const Body& b, bool along_x, Num d, const TileGrid& grid) {
    if (d.v == 0 || !std::isfinite(d.v)) return d;
    const Num pos = along_x ? b.x : b.y, size = along_x ? b.w : b.h;
    const int tile = along_x ? grid.tile_width() : grid.tile_height();
    const CellRange across = along_x ? grid.clip_rows(cells_of(b.y, b.h, grid.tile_height()))
                                     : grid.clip_cols(cells_of(b.x, b.w, grid.tile_width()));
    if (across.empty() || !(size.v > 0)) return d;
    const CellRange now = cells_of(pos, size, tile);
    const bool forward = d.v > 0;
    // The cells the move enters, beyond those the body overlaps already.
    CellRange entered = forward ? cells_of(pos + size, d, tile) : cells_of(pos + d, Num{-d.v, d.exact}, tile);
    if (forward) entered.first = std::max(entered.first, now.last + 1);
    else entered.last = std::min(entered.last, now.first - 1);
    entered = along_x ? grid.clip_cols(entered) : grid.clip_rows(entered);
    const bool down = !along_x && forward;
    for (int64_t i = 0, n = entered.last - entered.first + 1; i < n; ++i) {
        const int64_t c = forward ? entered.first + i : entered.last - i;
        for (int64_t k = across.first; k <= across.last; ++k) {
            const uint8_t cell = along_x ? grid.cell_in(c, k) : grid.cell_in(k, c);
            if (!stops(cell, down)) continue;
            const bool exact = pos.exact && size.exact;
            const double face = static_cast<double>(forward ? c : c + 1) * tile;
            return forward ? Num{face - (pos + size).v, exact} : Num{face - pos.v, exact};
        }
    }
    return d;
}

namespace {

// Whether a box at (x, y) overlaps a whole solid cell.
bool in_solid(const TileGrid& g, Num x, Num y, Num w, Num h) {
    const CellRange cols = g.clip_cols(cells_of(x, w, g.tile_width()));
    const CellRange rows = g.clip_rows(cells_of(y, h, g.tile_height()));
    for (int64_t r = rows.first; r <= rows.last; ++r)
        for (int64_t c = cols.first; c <= cols.last; ++c)
            if (g.cell_in(c, r) == kSolidCell) return true;
    return false;
}

// The least distance a box must move along one axis, in one direction, to
// overlap no whole solid cell: it tries the places where its leading face
// lies on a cell edge, nearest first, up to the first beyond the grid
// (where no cell is solid).
double way_out(const TileGrid& g, const Body& b, bool x_axis, bool forward) {
    const Num pos = x_axis ? b.x : b.y, size = x_axis ? b.w : b.h;
    const int tile = x_axis ? g.tile_width() : g.tile_height();
    const int64_t origin = x_axis ? g.origin_col() : g.origin_row();
    const int64_t count = x_axis ? g.cols() : g.rows();
    const CellRange now = cells_of(pos, size, tile);
    const bool exact = pos.exact && size.exact;
    // Leading face on edge e: forward, the near face (pos) on e·tile; back,
    // the far face (pos + size) on e·tile.
    int64_t e = forward ? now.first + 1 : now.last;
    const int64_t stop = forward ? origin + count : origin;
    for (;; e += forward ? 1 : -1) {
        const double edge = static_cast<double>(e) * tile;
        const Num to = forward ? Num{edge, exact} : Num{edge - size.v, exact};
        const bool free = x_axis ? !in_solid(g, to, b.y, b.w, b.h) : !in_solid(g, b.x, to, b.w, b.h);
        if (free || (forward ? e >= stop : e <= stop)) return std::fabs(to.v - pos.v);
    }
}

}  // namespace

bool put_out_of_solids(Body& b, const TileGrid& grid) {
    if (!(b.w.v > 0 && b.h.v > 0) || !in_solid(grid, b.x, b.y, b.w, b.h)) return false;
    const bool exact = b.x.exact && b.y.exact && b.w.exact && b.h.exact;
    const double up = way_out(grid, b, false, false), left = way_out(grid, b, true, false);
    const double right = way_out(grid, b, true, true), down = way_out(grid, b, false, true);
    const double least = std::min(std::min(up, left), std::min(right, down));
    if (least == up) {
        b.y = Num{b.y.v - up, exact};
        if (b.vy.v > 0) b.vy = Num::integer(0);
    } else if (least == left) {
        b.x = Num{b.x.v - left, exact};
        if (b.vx.v > 0) b.vx = Num::integer(0);
    } else if (least == right) {
        b.x = Num{b.x.v + right, exact};
        if (b.vx.v < 0) b.vx = Num::integer(0);
    } else {
        b.y = Num{b.y.v + down, exact};
        if (b.vy.v < 0) b.vy = Num::integer(0);
    }
    return true;
}

}  // namespace ds
