// SPDX-License-Identifier: MIT
// A cell's shape (cell_shape.hpp) placed in the world, and the few numbers
// every shape rule of semantics §12 reads from it: its x extent, its top and
// bottom over a span of x, and whether a box overlaps it. Everything is
// computed in doubles in one fixed order of operations, which the reference
// (reference.scm, "shaped cells") repeats on flonums, so both get the same
// bits; exactness is decided once, on the value written (exact_if).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "../cell_shape.hpp"
#include "../number.hpp"
#include "../tile_grid.hpp"

namespace ds::shape_math {

// [lo, hi) along x.
struct Span {
    double lo, hi;
};

// Whether v is an integer, as std::floor(v) == v says (infinities are, NaN
// is not), without the libm call std::floor is without SSE4.1: every
// landing and lift of an exact body asks.
inline bool integral_value(double v) {
    if (!(std::fabs(v) < 0x1p52)) return !std::isnan(v);  // every double this large is an integer
    return v == static_cast<double>(static_cast<int64_t>(v));
}
// The written value: exact when everything it came from was exact and it is
// an integer (semantics §12: a ramp's height at an odd x may be a half).
inline Num exact_if(bool exact, double v) { return {v, exact && integral_value(v)}; }

// std::clamp's own rule (lo when v < lo, hi when hi < v, else v): the
// reference spells it the same way, so a signed zero comes out the same.
inline double clamp(double v, double lo, double hi) { return v < lo ? lo : hi < v ? hi : v; }

struct Placed {
    const CellShape& s;
    const ShapeGeometry& g;
    double ox, oy;  // the cell's top-left corner, col·tw and row·th
    double left_, right_, top_, bottom_;  // the box in the world
    double ax, dx, dy, base;  // the first line's first x, run and rise, and (oy + ay)·dx
    double inv_dx;            // its LineGeometry::inv_dx

    // `shape` is one g.shape() gave: its doubles come from g's table.
    Placed(const CellShape& shape, int64_t col, int64_t row, const TileGrid& g)
        : Placed(shape, g.geometry(shape), col, row, g) {}
    // The shape of a cell known to be shaped, by its place in g's table.
    Placed(uint16_t id, int64_t col, int64_t row, const TileGrid& g)
        : Placed(g.shape_at(id), g.geometry_at(id), col, row, g) {}
    Placed(const CellShape& shape, const ShapeGeometry& d, int64_t col, int64_t row, const TileGrid& g)
        : s(shape), g(d), ox(static_cast<double>(col) * g.tile_width()), oy(static_cast<double>(row) * g.tile_height()),
          left_(ox + d.x0), right_(ox + d.x1), top_(oy + d.y0), bottom_(oy + d.y1),
          ax(d.line.ax), dx(d.line.dx), dy(d.line.dy), base((oy + d.line.ay) * dx), inv_dx(d.line.inv_dx) {}

    double left() const { return left_; }
    double right() const { return right_; }
    double box_top() const { return top_; }
    double box_bottom() const { return bottom_; }
    // Where the top is highest (a floor shape) or the bottom lowest (a
    // ceiling one), CellShape::apex, in the world.
    double apex() const { return ox + g.apex; }
    // Where the bottom is lowest, CellShape::under_apex, in the world.
    double under_apex() const { return ox + g.under_apex; }

    // The first slanted line's y at world x: ((oy + ay)·dx + ((x − ox) − ax)·dy) / dx,
    // one division (for a power-of-two run, the multiplication by 1/dx that
    // gives the same bits), so exact integers give the correctly rounded value.
    double line(double x) const {
        const double n = base + ((x - ox) - ax) * dy;
        return inv_dx != 0 ? n * inv_dx : n / dx;
    }
    // The same for line i (0 the first), in the same order of operations.
    double line(int i, double x) const {
        if (i == 0) return line(x);
        const LineGeometry& l = g.more[static_cast<size_t>(i - 1)];
        const double n = (oy + l.ay) * l.dx + ((x - ox) - l.ax) * l.dy;
        return l.inv_dx != 0 ? n * l.inv_dx : n / l.dx;
    }
    int lines() const { return 1 + g.n_more; }
    // A two-sided shape's underside line i at world x, in the same order
    // of operations.
    double under_line(int i, double x) const {
        const LineGeometry& l = g.under[static_cast<size_t>(i)];
        const double n = (oy + l.ay) * l.dx + ((x - ox) - l.ax) * l.dy;
        return l.inv_dx != 0 ? n * l.inv_dx : n / l.dx;
    }
    int under_lines() const { return g.n_under; }
    // The line that bounds the solid at x: the lowest (greatest y) of a
    // floor shape's lines, the highest of a ceiling shape's, the first wins
    // a tie. A convex polygon's roof is the lowest of its edges' lines at
    // every x, its underside the highest.
    double bound(double x) const {
        double v = line(x);
        for (int i = 1; i < lines(); ++i) {
            const double w = line(i, x);
            if (s.cut == Cut::Floor ? v < w : w < v) v = w;
        }
        return v;
    }
    // The line that bounds a two-sided shape's solid from below at x: the
    // highest of its underside's, the first wins a tie.
    double under_bound(double x) const {
        double v = under_line(0, x);
        for (int i = 1; i < under_lines(); ++i) v = std::min(v, under_line(i, x));
        return v;
    }
    // Whether the bottom is slanted: a ceiling shape's, a two-sided one's.
    bool slanted_below() const { return s.cut == Cut::Ceiling || g.n_under > 0; }
    // The top and bottom of the solid in the column at x (top ≥ bottom: none).
    double top(double x) const {
        return s.cut == Cut::Floor ? clamp(bound(x), box_top(), box_bottom()) : box_top();
    }
    double bottom(double x) const {
        if (s.cut == Cut::Ceiling) return clamp(bound(x), box_top(), box_bottom());
        return g.n_under > 0 ? clamp(under_bound(x), box_top(), box_bottom()) : box_bottom();
    }

    // The part of `span` over the shape, [a, b); false when none.
    bool over(Span span, double& a, double& b) const {
        a = std::max(span.lo, left());
        b = std::min(span.hi, right());
        return a < b;
    }
    // The highest top (least y) over [a, b) and the lowest bottom: the top
    // falls (the bottom rises) away from the apex on either side, so the
    // apex clamped to the span gives each, b (not in the span) as the limit;
    // for a ramp that is the end its line rises towards. One evaluation.
    double top_over(double a, double b) const { return top(clamp(apex(), a, b)); }
    double bottom_over(double a, double b) const {
        return bottom(clamp(s.cut == Cut::Ceiling ? apex() : under_apex(), a, b));
    }
    // Where a body over [a, b) meets the shape from above (its highest top)
    // and from below (its lowest bottom).
    double surface(double a, double b) const { return s.cut == Cut::Floor ? top_over(a, b) : box_top(); }
    double underside(double a, double b) const { return slanted_below() ? bottom_over(a, b) : box_bottom(); }
    // surface() and underside() over [a, b) at once (one pair of line
    // evaluations), and whether [a, b) holds solid (solid_over).
    bool extent(double a, double b, double& surface_y, double& underside_y) const {
        switch (s.cut) {
            case Cut::Floor:
                // A two-sided shape is convex: a box across [a, b) meets it
                // exactly when it meets [highest top, lowest bottom] there.
                surface_y = top_over(a, b), underside_y = g.n_under > 0 ? bottom_over(a, b) : box_bottom();
                return surface_y < underside_y;
            case Cut::Ceiling:
                surface_y = box_top(), underside_y = bottom_over(a, b);
                return underside_y > surface_y;
            case Cut::None: break;
        }
        surface_y = box_top(), underside_y = box_bottom();
        return true;
    }
    // Whether [a, b) holds any solid column: a ramp's columns past the end
    // of its slant can be empty.
    bool solid_over(double a, double b) const {
        switch (s.cut) {
            case Cut::Floor: return top_over(a, b) < (g.n_under > 0 ? bottom_over(a, b) : box_bottom());
            case Cut::Ceiling: return bottom_over(a, b) > box_top();
            case Cut::None: break;
        }
        return true;
    }
    // Whether the point lies in the solid: in the box (half-open, as every
    // box) and, for a ramp, on the kept side of the slant or on it.
    bool holds(double x, double y) const {
        if (!(left() <= x && x < right() && box_top() <= y && y < box_bottom())) return false;
        if (s.cut == Cut::Floor) return y >= bound(x) && (g.n_under == 0 || y <= under_bound(x));
        if (s.cut == Cut::Ceiling) return y <= bound(x);
        return true;
    }
    // Strict overlap with the box [span) × [top, bottom).
    bool overlaps(Span span, double top_y, double bottom_y) const {
        double a, b, surface_y, underside_y;
        return over(span, a, b) && extent(a, b, surface_y, underside_y) && top_y < underside_y &&
               bottom_y > surface_y;
    }
};

}  // namespace ds::shape_math
