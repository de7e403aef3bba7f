// SPDX-License-Identifier: MIT
#include "tile_clip.hpp"

#include <algorithm>
#include <cmath>

#include "placed_shape.hpp"

namespace ds {

namespace {

using shape_math::exact_if;
using shape_math::Placed;
using shape_math::Span;

// Stops a push as a whole cell: solid always, one-way a move down. A shaped
// cell stops it by its shape (shape_stop).
bool stops(uint8_t cell, bool down) { return cell == kSolidCell || (down && cell == kOneWayCell); }

// Where slanted line l of p is at height y: the x with line(x) = y,
// ((y·dx − (oy + ay)·dx) / dy + ax) + ox, in that order (the reference
// repeats it), so exact integers give the correctly rounded value.
double line_x(const Placed& p, Slant l, double y) {
    const double ax = l.ax, dx = l.bx - l.ax, dy = l.by - l.ay;
    return ((y * dx - (p.oy + l.ay) * dx) / dy + ax) + p.ox;
}

// Where a box moving along x from `lead` to `reach` meets, with its corner
// at height `level`, the slants of one side of p (its top's when `floor`,
// its bottom's else) that face the move before `apex`: the farthest of
// their lines at that height, as the solid is on the kept side of every
// one. False when none faces it or the box does not get there.
template <typename SlantAt>
bool corner_stop(const Placed& p, SlantAt slant, int n, bool floor, double level, double apex, bool fwd,
                 double lead, double reach, double& stop) {
    bool facing = false;
    double x = 0;
    for (int i = 0; i < n; ++i) {
        const Slant l = slant(i);
        const bool rising = fwd ? l.by < l.ay : l.by > l.ay;  // the line climbs the way the box moves
        if (rising != floor) continue;
        const double xi = line_x(p, l, level);
        if (!facing || (fwd ? x < xi : xi < x)) x = xi;
        facing = true;
    }
    if (!facing) return false;
    const double at = fwd ? std::max(x, p.left()) : std::min(x, p.right());
    const bool met = fwd ? lead <= at && at < reach && at < p.right() && at < apex
                         : reach < at && at <= lead && at > p.left() && at > apex;
    if (met) stop = at - lead;
    return met;
}

// How far (signed as d, |result| < |d|) the box of b can move along an axis
// before it meets the solid of shape p, or false when the move never meets
// it (or the box overlaps it already): moving along y, the feet onto its
// surface (a move down) or the head onto its underside (up), as the y step
// lands (§12); moving along x, the leading face onto its near side where
// the box spans solid there, as the x step walls, else, where slants face
// the move (a floor's rising, a ceiling's falling, the way the box moves)
// before the apex, the box's corner onto them: its feet for a floor, its
// head for a ceiling — the farthest of their lines at that height, as the
// solid is on the kept side of every one. A two-sided shape has both: its
// feet onto the top's slants when they are no lower than the near side's
// top, its head onto the underside's when no higher than that side's
// bottom, the nearer of the two. A one-way shape stops only a move down.
bool shape_stop(const Body& b, const Placed& p, bool along_x, double d, double& stop) {
    const bool fwd = d > 0;
    const double head = b.y.v, feet = (b.y + b.h).v;
    if (p.s.one_way && (along_x || !fwd)) return false;
    if (!along_x) {
        double a, z, top, under;
        if (!p.over({b.x.v, (b.x + b.w).v}, a, z) || !p.extent(a, z, top, under)) return false;
        if (fwd && feet <= top && top < feet + d) return stop = top - feet, true;
        if (!fwd && head >= under && under > head + d) return stop = under - head, true;
        return false;
    }
    const double lead = fwd ? (b.x + b.w).v : b.x.v, reach = lead + d;
    const double side = fwd ? p.left() : p.right();
    const bool crossed = fwd ? lead <= side && side < reach : reach < side && side <= lead;
    if (crossed && head < p.bottom(side) && feet > p.top(side)) return stop = side - lead, true;
    if (!(head < p.box_bottom() && feet > p.box_top())) return false;
    if (p.s.cut == Cut::None) return false;
    auto main_slant = [&](int i) { return p.s.slant(i); };
    const bool floor = p.s.cut == Cut::Floor;
    if (!p.s.two_sided())
        return corner_stop(p, main_slant, p.lines(), floor, floor ? feet : head, p.apex(), fwd, lead, reach, stop);
    double by_feet = 0, by_head = 0;
    const bool feet_met = feet <= p.top(side) &&
                          corner_stop(p, main_slant, p.lines(), true, feet, p.apex(), fwd, lead, reach, by_feet);
    const bool head_met =
        head >= p.bottom(side) &&
        corner_stop(p, [&](int i) { return p.s.under[static_cast<size_t>(i)]; }, p.under_lines(), false, head,
                    p.under_apex(), fwd, lead, reach, by_head);
    if (feet_met && (!head_met || std::fabs(by_feet) <= std::fabs(by_head))) return stop = by_feet, true;
    if (head_met) return stop = by_head, true;
    return false;
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
    const CellRange reach = entered;
    if (forward) entered.first = std::max(entered.first, now.last + 1);
    else entered.last = std::min(entered.last, now.first - 1);
    entered = along_x ? grid.clip_cols(entered) : grid.clip_rows(entered);
    const bool down = !along_x && forward;
    Num cut = d;
    for (int64_t i = 0, n = entered.last - entered.first + 1; i < n; ++i) {
        const int64_t c = forward ? entered.first + i : entered.last - i;
        bool hit = false;
        for (int64_t k = across.first; k <= across.last && !hit; ++k)
            hit = stops(along_x ? grid.cell_in(c, k) : grid.cell_in(k, c), down);
        if (!hit) continue;
        const bool exact = pos.exact && size.exact;
        const double face = static_cast<double>(forward ? c : c + 1) * tile;
        cut = forward ? Num{face - (pos + size).v, exact} : Num{face - pos.v, exact};
        break;
    }
    if (!grid.has_shapes()) return cut;
    // Shapes in every cell the box overlaps now or on its way up to the
    // cut, nearest stop first: a shape can stop a box already in its cell.
    CellRange swept = along_x ? grid.clip_cols({std::min(now.first, reach.first), std::max(now.last, reach.last)})
                              : grid.clip_rows({std::min(now.first, reach.first), std::max(now.last, reach.last)});
    const bool exact = b.x.exact && b.y.exact && b.w.exact && b.h.exact;
    for (int64_t c = swept.first; c <= swept.last; ++c)
        for (int64_t k = across.first; k <= across.last; ++k) {
            const int64_t col = along_x ? c : k, row = along_x ? k : c;
            if (grid.cell_in(col, row) != kShapedCell) continue;
            double stop;
            if (shape_stop(b, Placed(grid.shape_id_in(col, row), col, row, grid), along_x, cut.v, stop) &&
                std::fabs(stop) < std::fabs(cut.v))
                cut = exact_if(exact, stop);
        }
    return cut;
}

namespace {

// Whether a box at (x, y) overlaps a whole solid cell or the solid of a
// shape (not a one-way one): what put-out counts as inside.
bool inside(const TileGrid& g, Num x, Num y, Num w, Num h) {
    const CellRange cols = g.clip_cols(cells_of(x, w, g.tile_width()));
    const CellRange rows = g.clip_rows(cells_of(y, h, g.tile_height()));
    const Span span{x.v, (x + w).v};
    for (int64_t r = rows.first; r <= rows.last; ++r)
        for (int64_t c = cols.first; c <= cols.last; ++c) {
            const uint8_t cell = g.cell_in(c, r);
            if (cell == kSolidCell) return true;
            if (cell != kShapedCell) continue;
            const uint16_t id = g.shape_id_in(c, r);
            if (!g.shape_at(id).one_way && Placed(id, c, r, g).overlaps(span, y.v, (y + h).v)) return true;
        }
    return false;
}

// One direction of the put-out search: the place reached so far (the
// leading face's coordinate, or the position moving up or left is the
// near face's), and whether the box is free there.
struct Way {
    bool x_axis, forward;
    Num at;        // the box's position along the axis at this place
    bool free = false;
};

// The nearest place beyond `w.at` that could be free: where the box has
// left every solid it overlaps at w.at — a whole cell by its far edge, a
// shape moving along y by its surface (up) or underside (down), along x
// by its box's side. Everything between still overlaps one of them.
Num next_place(const TileGrid& g, const Body& b, const Way& w, bool exact) {
    const Num x = w.x_axis ? w.at : b.x, y = w.x_axis ? b.y : w.at;
    const CellRange cols = g.clip_cols(cells_of(x, b.w, g.tile_width()));
    const CellRange rows = g.clip_rows(cells_of(y, b.h, g.tile_height()));
    const Span span{x.v, (x + b.w).v};
    const Num size = w.x_axis ? b.w : b.h;
    const double tile = w.x_axis ? g.tile_width() : g.tile_height();
    // The leading face's target: the farthest any overlapped solid asks.
    double face = w.forward ? -INFINITY : INFINITY;
    auto ask = [&](double f) { face = w.forward ? std::max(face, f) : std::min(face, f); };
    for (int64_t r = rows.first; r <= rows.last; ++r)
        for (int64_t c = cols.first; c <= cols.last; ++c) {
            const uint8_t cell = g.cell_in(c, r);
            const int64_t along = w.x_axis ? c : r;
            if (cell == kSolidCell) {
                ask(static_cast<double>(w.forward ? along + 1 : along) * tile);
                continue;
            }
            if (cell != kShapedCell) continue;
            const uint16_t id = g.shape_id_in(c, r);
            const Placed p(id, c, r, g);
            if (g.shape_at(id).one_way || !p.overlaps(span, y.v, (y + b.h).v)) continue;
            double a, z;
            p.over(span, a, z);
            if (w.x_axis) ask(w.forward ? p.right() : p.left());
            else ask(w.forward ? p.underside(a, z) : p.surface(a, z));
        }
    // Forward the near face goes to the target, back the far face does.
    return exact_if(exact, w.forward ? face : face - size.v);
}

}  // namespace

bool put_out_of_solids(Body& b, const TileGrid& grid) {
    // A box at no finite place has no way out to measure.
    const bool finite = std::isfinite(b.x.v) && std::isfinite(b.y.v) && std::isfinite(b.w.v) && std::isfinite(b.h.v);
    if (!finite || !(b.w.v > 0 && b.h.v > 0) || !inside(grid, b.x, b.y, b.w, b.h)) return false;
    const bool exact = b.x.exact && b.y.exact && b.w.exact && b.h.exact;
    // The four directions searched side by side, always the one nearest the
    // start, so the search ends at the shortest way out having gone no
    // further in any direction: its cost is that distance's cells times the
    // body's, whatever the size of the map (ties: up, left, right, down).
    Way ways[4] = {{false, false, b.y}, {true, false, b.x}, {true, true, b.x}, {false, true, b.y}};
    auto dist = [&](const Way& w) { return std::fabs(w.at.v - (w.x_axis ? b.x : b.y).v); };
    for (;;) {
        Way* near = &ways[0];
        for (Way& w : ways)
            if (dist(w) < dist(*near)) near = &w;
        if (near->free) break;
        const Num x = near->x_axis ? near->at : b.x, y = near->x_axis ? b.y : near->at;
        if (!inside(grid, x, y, b.w, b.h)) {
            near->free = true;
            continue;
        }
        const Num next = next_place(grid, b, *near, exact);
        // Every solid the box overlaps lies wholly ahead of where it is, so
        // the next place is beyond it; rounding at enormous coordinates
        // could say otherwise, and the search must still move on.
        const bool beyond = near->forward ? next.v > near->at.v : next.v < near->at.v;
        near->at = beyond ? next : Num::flonum(std::nextafter(near->at.v, near->forward ? INFINITY : -INFINITY));
    }
    Way* out = &ways[0];
    for (Way& w : ways)
        if (dist(w) < dist(*out)) out = &w;
    Num& pos = out->x_axis ? b.x : b.y;
    Num& vel = out->x_axis ? b.vx : b.vy;
    pos = out->at;
    if (out->forward ? vel.v < 0 : vel.v > 0) vel = Num::integer(0);
    return true;
}

}  // namespace ds
