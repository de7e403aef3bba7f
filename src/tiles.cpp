// SPDX-License-Identifier: MIT
#include "tiles.hpp"

#include <algorithm>
#include <cmath>

#include "bounce.hpp"
#include "detail/body_axis.hpp"
#include "detail/placed_shape.hpp"
#include "steps.hpp"

namespace ds {

namespace {

// One axis of a body as a tile step sees it, so x and y share a single
// resolution routine: the body's axis plus this step's move and cell size.
struct TileAxis {
    BodyAxis body;
    Num move;  // this (sub-)frame's displacement: vel, or vel·h
    int tile;
};

// The cells to test along the moving axis. Discrete: the box as it is now.
// Swept: the box plus every cell its leading edge crossed this frame, which
// equals the box whenever |v| ≤ size.
CellRange candidates(const TileAxis& t, CollisionMode mode) {
    const BodyAxis& a = t.body;
    if (mode == CollisionMode::Discrete || !(a.size.v > 0)) return cells_of(a.pos, a.size, t.tile);
    const Num start = a.pos - t.move;  // where the box began the move
    if (a.vel.v > 0) {
        const Num lead_start = start + a.size;  // the right (bottom) edge before the move
        const Num lo = lead_start.v < a.pos.v ? lead_start : a.pos;
        return cells_of(lo, (a.pos + a.size) - lo, t.tile);
    }
    const Num hi = start.v > a.pos.v + a.size.v ? start : a.pos + a.size;
    return cells_of(a.pos, hi - a.pos, t.tile);
}

// Puts the box flush against `edge` on the side it moves from (its far side
// on the edge moving forward, its near side moving back): exact when its
// position and size were.
void snap_flush(const BodyAxis& a, double edge, bool forward) {
    const bool exact = a.pos.exact && a.size.exact;
    a.pos = forward ? Num{edge - a.size.v, exact} : Num{edge, exact};
}

// What a walk along the candidate cells met first.
enum class Met { Nothing, Whole, Shape };

// Walks candidate cells from the side the body moves from, so the first
// cell met is the one it reaches first. `kind(c, k)`: < 0 for a whole cell
// that stops the move, which puts the body flush against it; > 0 for a
// shaped cell the move may meet, which leaves the rest to the shape rules
// (they treat every whole cell as this walk does); 0 for neither.
// `met_at`: where a shape was met along the axis (c).
template <typename Kind>
Met walk_axis(const TileAxis& t, CellRange along, CellRange across, Kind kind, int64_t& met_at) {
    const BodyAxis& a = t.body;
    if (along.empty() || across.empty()) return Met::Nothing;
    const bool forward = a.vel.v > 0;
    for (int64_t i = 0, n = along.last - along.first + 1; i < n; ++i) {
        const int64_t c = forward ? along.first + i : along.last - i;
        for (int64_t k = across.first; k <= across.last; ++k) {
            const int v = kind(c, k);
            if (v == 0) continue;
            if (v > 0) {
                met_at = c;
                return Met::Shape;
            }
            snap_flush(a, static_cast<double>(forward ? c : c + 1) * t.tile, forward);
            a.vel = Num::integer(0);
            return Met::Whole;
        }
    }
    return Met::Nothing;
}

// A contact body's #:blocked (semantics §10): the step owns its axis's
// sides, set from this call alone, or, in a later sub-frame, added.
void note_blocked(Body& b, uint8_t axis, uint8_t sides, SubStep s) {
    if (!b.contacts) return;
    const uint8_t kept = s.gather ? b.blocked : static_cast<uint8_t>(b.blocked & ~axis);
    b.blocked = static_cast<uint8_t>((kept & kSidesAll) | sides);
}

// The velocity a stop leaves on its axis (the steps zero it first): the
// rebound of the velocity the body hit with (§13). A carried move leaves
// the rider's velocities alone, so it never rebounds.
Num stop_velocity(Num hit, const Body& b, SubStep s) {
    return s.carried ? Num::integer(0) : rebound(hit, b.bounce);
}

uint8_t side(bool stopped, Num vel, uint8_t forward, uint8_t backward) {
    return stopped ? (vel.v > 0 ? forward : backward) : 0;
}

// ---- shaped cells (semantics §12). Only grids that hold a shape come here;
// every whole cell is treated exactly as resolve_axis treats it.
using shape_math::exact_if;
using shape_math::Placed;
using shape_math::Span;

// A position a shape rule computes depends on the whole box.
bool box_exact(const Body& b) { return b.x.exact && b.y.exact && b.w.exact && b.h.exact; }

// Whether a move along x enters shape p through its near side (the side
// facing the move) rather than over its slant: the box's leading edge
// crosses that side, and the box spans some of the solid there.
bool enters_side(const Placed& p, bool fwd, double lead_before, double lead_after, double top, double bottom) {
    const double side = fwd ? p.left() : p.right();
    const bool crossed = fwd ? lead_before <= side && side < lead_after : lead_after < side && side <= lead_before;
    return crossed && top < p.bottom(side) && bottom > p.top(side);
}

// Whether feet at `feet` were on or above one-way ramp p where the box's
// leading edge met it: only then does it carry the body up (§9, §12).
bool enters_from_above(const Placed& p, bool fwd, double lead_before, double feet) {
    const double at = fwd ? std::max(p.left(), lead_before) : std::min(p.right(), lead_before);
    return feet <= p.top(at);
}

struct XMove {
    bool fwd;
    double lead_before, lead_after;
    Span sweep;  // where the box went this move (swept), or where it is (discrete)
    int lifted = 0;  // +1 once a floor ramp lifted the body, −1 once a ceiling ramp pushed it down
    // A scan met a solid shape that a move along y could push the box into
    // (a ceiling ramp, a part-tile box, a floor ramp above the head): after
    // a lift the box must be checked against every solid (overlaps_solid).
    // Without one, with the rows unchanged and no wall met, every column of
    // the final box was scanned at its final rows and nothing there can
    // overlap it.
    bool unsure = false;
};

// Whether a move along y could push a box over [top, bottom) into solid
// shape p, which it does not overlap and does not climb: a floor shape only
// from below its box, unless its underside is slanted (a two-sided shape
// beside the box may reach under a lifted head).
bool could_meet(const Placed& p, double top) {
    return p.s.cut != Cut::Floor || p.s.two_sided() || top >= p.box_bottom();
}

// What the ramps of one column, scanned at the box's present rows, would
// do to it: lift it onto the highest floor ramp top it overlaps over its
// sweep, push it under the lowest ceiling ramp bottom.
struct Climb {
    double new_feet, new_head;
    bool up = false, down = false, ceilings = false, one_way_below = false;
};

// One shaped cell's part in a climb scan of a box whose head and feet are
// at `head` and `feet`. Always inlined, as apply_climb is: both run for
// every shaped column a walker crosses, and a call cost about as much.
[[gnu::always_inline]] inline void climb_cell(const Body& b, const Placed& p, XMove& m, double head, double feet,
                                               Climb& k) {
    const CellShape& sh = p.s;
    if (!sh.ramp()) {
        m.unsure = m.unsure || !sh.one_way;
        return;
    }
    double a, z, t, under;
    if (!p.over(m.sweep, a, z) || !p.extent(a, z, t, under)) return;
    if (sh.cut == Cut::Floor) {
        if (sh.one_way && (b.drop_through || !enters_from_above(p, m.fwd, m.lead_before, feet))) {
            k.one_way_below = k.one_way_below || !b.drop_through;  // a lift may bring the feet above it
            return;
        }
        if (head < under && feet > t) {
            k.up = true;
            if (t < k.new_feet) k.new_feet = t;
        }
        m.unsure = m.unsure || (!sh.one_way && head >= under);
    } else if (!sh.one_way) {
        k.ceilings = true;
        m.unsure = true;
        if (feet > p.box_top() && head < under) {
            k.down = true;
            if (k.new_head < under) k.new_head = under;
        }
    }
}

enum class Climbed { Done, Again, Squeezed };

// Moves the box as a climb scan says and updates `rows` to its rows:
// Done when no ramp of the column can move it further, Again when the
// column must be scanned again at the new rows (a fast body on a long
// ramp), Squeezed when it cannot move (ramps push it both ways).
[[gnu::always_inline]] inline Climbed apply_climb(Body& b, const TileGrid& g, XMove& m, const Climb& k,
                                                  CellRange& rows) {
    if (!k.up && !k.down) return Climbed::Done;
    if ((k.up && k.down) || (k.up && m.lifted < 0) || (k.down && m.lifted > 0)) return Climbed::Squeezed;
    const bool exact = box_exact(b);
    b.y = k.up ? exact_if(exact, k.new_feet - b.h.v) : exact_if(exact, k.new_head);
    m.lifted = k.up ? 1 : -1;
    const CellRange now = g.clip_rows(cells_of(b.y, b.h, g.tile_height()));
    const bool same_rows = now.first == rows.first && now.last == rows.last;
    rows = now;
    // Over the same rows, a lift onto the highest of the floor ramps
    // leaves none to climb; only a ceiling ramp could now push back.
    return k.up && !k.ceilings && !k.one_way_below && same_rows ? Climbed::Done : Climbed::Again;
}

// Column c at the box's rows, in one pass: the nearest side of a solid the
// move runs into there (true; `whole`: a whole cell's), else the first
// climb scan, applied. `rows`: the box's rows, kept up to date.
bool scan_column(Body& b, const TileGrid& g, int64_t c, CellRange& rows, XMove& m, double& wall, bool& whole,
                 Climbed& climbed) {
    const double top = b.y.v, bottom = (b.y + b.h).v;
    bool found = false;
    Climb k{bottom, top};
    for (int64_t r = rows.first; r <= rows.last; ++r) {
        const uint8_t cell = g.cell_in(c, r);
        if (cell == kSolidCell) {
            wall = static_cast<double>(m.fwd ? c : c + 1) * g.tile_width();
            whole = true;
            return true;
        }
        if (cell != kShapedCell) continue;
        const Placed p(g.shape_id_in(c, r), c, r, g);
        if (!p.s.one_way) {
            if (enters_side(p, m.fwd, m.lead_before, m.lead_after, top, bottom)) {
                const double side = m.fwd ? p.left() : p.right();
                if (!found || (m.fwd ? side < wall : side > wall)) wall = side;
                found = true;
            } else {
                m.unsure = m.unsure || could_meet(p, top);
            }
        }
        // Only read when no wall is met: a stopped move is checked whole.
        if (!found) climb_cell(b, p, m, top, bottom, k);
    }
    whole = false;
    if (!found) climbed = apply_climb(b, g, m, k, rows);
    return found;
}

// The climb scans of column c after the first, while the new rows bring
// more ramps; false when the box is squeezed or the scans do not end.
bool climb_again(Body& b, const TileGrid& g, int64_t c, CellRange& rows, XMove& m) {
    for (int64_t guard = 1; guard <= static_cast<int64_t>(g.rows()) + 1; ++guard) {
        const double head = b.y.v, feet = (b.y + b.h).v;
        Climb k{feet, head};
        for (int64_t r = rows.first; r <= rows.last; ++r)
            if (const CellShape* sh = g.shape(c, r)) climb_cell(b, Placed(*sh, c, r, g), m, head, feet, k);
        switch (apply_climb(b, g, m, k, rows)) {
            case Climbed::Done: return true;
            case Climbed::Squeezed: return false;
            case Climbed::Again: break;
        }
    }
    return false;
}

// `cols`: the move's candidate columns, `rows0` the box's rows, both
// clipped to the grid.
bool shaped_x(Body& b, const TileGrid& g, CollisionMode mode, SubStep s, CellRange cols, CellRange rows0) {
    const Num move = s.share(b.vx);
    const Num x_start = b.x - move, y_start = b.y;
    XMove m{b.vx.v > 0, 0, 0, {}};
    m.lead_before = m.fwd ? (x_start + b.w).v : x_start.v;
    m.lead_after = m.fwd ? (b.x + b.w).v : b.x.v;
    m.sweep = mode == CollisionMode::Discrete ? Span{b.x.v, (b.x + b.w).v}
              : m.fwd                         ? Span{x_start.v, (b.x + b.w).v}
                                              : Span{b.x.v, (x_start + b.w).v};
    bool stopped = false, shape_wall = false, squeezed = false;
    CellRange rows = rows0;
    for (int64_t i = 0, n = cols.last - cols.first + 1; i < n && !cols.empty(); ++i) {
        const int64_t c = m.fwd ? cols.first + i : cols.last - i;
        double wall = 0;
        bool whole = false;
        Climbed climbed = Climbed::Done;
        if (scan_column(b, g, c, rows, m, wall, whole, climbed)) {
            snap_flush(along_x(b), wall, m.fwd);
            stopped = true;
            shape_wall = !whole;
            break;
        }
        if (climbed == Climbed::Squeezed || (climbed == Climbed::Again && !climb_again(b, g, c, rows, m))) {
            squeezed = true;
            break;
        }
    }
    // A move that leaves the box in a solid (lifted into a ceiling, or
    // stopped by a part-tile box beside a ramp) is not made at all.
    auto must_check = [&] {
        if (shape_wall) return true;
        if (m.lifted == 0) return false;
        // Stopped at a wall, the box is not where the scans saw it (the
        // discrete rule may even put it behind where it started).
        if (stopped) return true;
        return m.unsure || rows.first != rows0.first || rows.last != rows0.last;
    };
    if (squeezed || (must_check() && overlaps_solid(b, g))) {
        b.x = x_start;
        b.y = y_start;
        stopped = true;
    }
    if (stopped) b.vx = Num::integer(0);
    return stopped;
}

// `rows`: the candidate rows from the first that may stop the move (the
// walk met nothing before it), `cols` the body's columns, both clipped;
// `stops(cell, r)`: a whole cell that stops this move (the whole-cell
// walk's own rule, solid or one-way).
template <typename Stops>
bool shaped_y(Body& b, const TileGrid& g, SubStep s, CellRange rows, CellRange cols, Stops stops) {
    const Num move = s.share(b.vy);
    const bool fwd = b.vy.v > 0;
    const bool may_land = fwd && !b.drop_through;
    const double feet_before = (b.y - move + b.h).v, head_before = (b.y - move).v;
    const double feet = (b.y + b.h).v, head = b.y.v;
    const double th = g.tile_height();
    const Span span{b.x.v, (b.x + b.w).v};
    for (int64_t i = 0, n = rows.last - rows.first + 1; i < n; ++i) {
        const int64_t r = fwd ? rows.first + i : rows.last - i;
        bool found = false;
        double stop = 0;
        for (int64_t c = cols.first; c <= cols.last; ++c) {
            const uint8_t cell = g.cell_in(c, r);
            if (stops(cell, r)) {
                snap_flush(along_y(b), static_cast<double>(fwd ? r : r + 1) * th, fwd);
                b.vy = Num::integer(0);
                return true;
            }
            if (cell != kShapedCell) continue;
            const uint16_t id = g.shape_id_in(c, r);
            if (g.shape_at(id).one_way && !may_land) continue;
            const Placed p(id, c, r, g);
            double a, z, top, under;
            if (!p.over(span, a, z) || !p.extent(a, z, top, under)) continue;
            if (fwd) {
                if (feet_before <= top && top < feet && (!found || top < stop)) stop = top, found = true;
            } else {
                if (head_before >= under && under > head && (!found || under > stop)) stop = under, found = true;
            }
        }
        if (found) {
            b.y = exact_if(box_exact(b), fwd ? stop - b.h.v : stop);
            b.vy = Num::integer(0);
            return true;
        }
    }
    return false;
}

// A body that stood on the ground last frame and walks on follows the
// ground down: onto the highest top under it no further below its feet
// than |vx| × the grid's steepest ramp (§12). Never for a carried move.
bool snap_down(Body& b, const TileGrid& g, SubStep s) {
    if (!b.gravity || !b.on_ground || s.carried) return false;
    const double reach = std::fabs(s.share(b.vx).v) * g.steepest_ramp();
    if (!(reach > 0)) return false;
    const double feet = (b.y + b.h).v, lowest = feet + reach;
    const CellRange rows = g.clip_rows({cell_of(b.y + b.h, g.tile_height()), cell_of(Num::flonum(lowest), g.tile_height())});
    const CellRange cols = g.clip_cols(cells_of(b.x, b.w, g.tile_width()));
    const Span span{b.x.v, (b.x + b.w).v};
    for (int64_t r = rows.first; r <= rows.last && !cols.empty(); ++r) {
        bool found = false;
        double ground = 0;
        for (int64_t c = cols.first; c <= cols.last; ++c) {
            const uint8_t cell = g.cell_in(c, r);
            double top;
            if (cell == kSolidCell || (cell == kOneWayCell && !b.drop_through)) {
                top = static_cast<double>(r) * g.tile_height();
            } else if (cell == kShapedCell) {
                const CellShape& sh = *g.shape(c, r);
                const Placed p(sh, c, r, g);
                double a, z, under;
                if ((sh.one_way && b.drop_through) || !p.over(span, a, z) || !p.extent(a, z, top, under)) continue;
            } else {
                continue;
            }
            if (feet <= top && top <= lowest && (!found || top < ground)) ground = top, found = true;
        }
        if (found) {
            b.y = exact_if(box_exact(b), ground - b.h.v);
            b.vy = Num::integer(0);
            return true;
        }
    }
    return false;
}

}  // namespace

bool resolve_tile_collisions_x(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s) {
    if (b.skips(kSkipTileX)) return false;
    if (!grid || b.vx.v == 0) {
        note_blocked(b, kSidesX, 0, s);
        return false;
    }
    const Num vx = b.vx;
    const TileAxis a{along_x(b), s.share(b.vx), grid->tile_width()};
    const CellRange cols = grid->clip_cols(candidates(a, mode));
    const CellRange rows = grid->clip_rows(cells_of(b.y, b.h, grid->tile_height()));
    // The shape rules give what the whole-cell walk gives until the walk
    // meets a shaped cell: most moves in a map with ramps never do.
    int64_t met_at = 0;
    const Met met = grid->has_shapes() ? walk_axis(a, cols, rows, [&](int64_t c, int64_t r) {
        const uint8_t k = grid->cell_in(c, r);
        return k == kShapedCell ? 1 : k == kSolidCell ? -1 : 0;
    }, met_at)
                                       : walk_axis(a, cols, rows, [&](int64_t c, int64_t r) {
        return grid->cell_in(c, r) == kSolidCell ? -1 : 0;
    }, met_at);
    const bool stopped = met == Met::Shape ? shaped_x(b, *grid, mode, s, cols, rows) : met == Met::Whole;
    if (stopped) b.vx = stop_velocity(vx, b, s);
    note_blocked(b, kSidesX, side(stopped, vx, kSideRight, kSideLeft), s);
    return true;
}

bool resolve_tile_collisions_y(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s) {
    if (b.skips(kSkipTileY)) return false;
    if (!grid || b.vy.v == 0) {
        note_blocked(b, kSidesY, 0, s);
        return false;
    }
    const Num vy = b.vy;
    const TileAxis a{along_y(b), s.share(b.vy), grid->tile_height()};
    const CellRange rows = grid->clip_rows(candidates(a, mode));
    const CellRange cols = grid->clip_cols(cells_of(b.x, b.w, grid->tile_width()));
    // A one-way cell stops a body falling onto it whose feet were at or above
    // its top when this move began (semantics §9); never one rising or
    // dropping through.
    const bool may_land = b.vy.v > 0 && !b.drop_through;
    const double feet_before = (b.y - a.move + b.h).v;
    const double th = grid->tile_height();
    auto stops_as = [&](uint8_t cell, int64_t r) {
        return cell == kSolidCell ||
               (may_land && cell == kOneWayCell && feet_before <= static_cast<double>(r) * th);
    };
    bool stopped;
    // A shape can stop the move only if the feet (moving down) or the head
    // (up) crossed into its box's rows of px: a shape in the row a body
    // stands in, beside it, does not send it down the shape rules.
    const double feet = (b.y + b.h).v, head = b.y.v, head_before = (b.y - a.move).v;
    auto may_stop = [&](int64_t r, int64_t c) {
        const ShapeGeometry& d = grid->geometry_at(grid->shape_id_in(c, r));
        const double oy = static_cast<double>(r) * th, y0 = oy + d.y0, y1 = oy + d.y1;
        return vy.v > 0 ? feet > y0 && feet_before < y1 : head < y1 && head_before > y0;
    };
    int64_t met_at = 0;
    const Met met = grid->has_shapes() ? walk_axis(a, rows, cols, [&](int64_t r, int64_t c) {
        const uint8_t cell = grid->cell_in(c, r);
        if (cell == kShapedCell) return may_stop(r, c) ? 1 : 0;
        return stops_as(cell, r) ? -1 : 0;
    }, met_at)
                                       : walk_axis(a, rows, cols, [&](int64_t r, int64_t c) {
        return stops_as(grid->cell_in(c, r), r) ? -1 : 0;
    }, met_at);
    if (met == Met::Shape) {
        const CellRange from = vy.v > 0 ? CellRange{met_at, rows.last} : CellRange{rows.first, met_at};
        stopped = shaped_y(b, *grid, s, from, cols, stops_as);
    } else {
        stopped = met == Met::Whole;
    }
    if (stopped) b.vy = stop_velocity(vy, b, s);
    // Not stopped: a walker may follow a ramp down (§12), which is no hit.
    if (!stopped && grid->has_shapes() && vy.v > 0) stopped = snap_down(b, *grid, s);
    note_blocked(b, kSidesY, side(stopped, vy, kSideDown, kSideUp), s);
    return true;
}

bool overlaps_solid(const Body& b, const TileGrid& grid) {
    const CellRange cols = grid.clip_cols(cells_of(b.x, b.w, grid.tile_width()));
    const CellRange rows = grid.clip_rows(cells_of(b.y, b.h, grid.tile_height()));
    const shape_math::Span span{b.x.v, (b.x + b.w).v};
    for (int64_t r = rows.first; r <= rows.last; ++r)
        for (int64_t c = cols.first; c <= cols.last; ++c) {
            if (grid.solid(c, r)) return true;
            const CellShape* sh = grid.shape(c, r);
            if (sh && !sh->one_way && shape_math::Placed(*sh, c, r, grid).overlaps(span, b.y.v, (b.y + b.h).v))
                return true;
        }
    return false;
}

}  // namespace ds
