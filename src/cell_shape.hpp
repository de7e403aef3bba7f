// SPDX-License-Identifier: MIT
// The solid part of a cell that is not the whole cell (semantics §12): a
// part-tile box, a ramp — a box cut by one slanted line — or a box cut by
// several slanted lines on one side (a convex polygon's roof or underside)
// or on both (a diamond, an octagon).
// Plain data, in whole px from the cell's top-left corner, so a grid keeps
// one small table of them and every rule reads the same numbers the
// reference does.
#pragma once
#include <array>
#include <cstdint>

#include "constants.hpp"
#include "export.hpp"

namespace ds {

// Which side of the slanted lines a shape keeps.
enum class Cut : int8_t {
    None = 0,      // a part-tile box: the box is the shape
    Floor = 1,     // what lies below every line (y grows down): a ramp or roof to walk on
    Ceiling = -1,  // what lies above every line: a ramp or underside to bump into from below
};

// A slanted line through (ax, ay) and (bx, by), ax < bx, ay ≠ by.
struct Slant {
    int32_t ax = 0, ay = 0, bx = 0, by = 0;
    bool operator==(const Slant&) const = default;
};

struct DOWNSTROKE_API CellShape {
    // The box [x0, x1) × [y0, y1), 0 ≤ x0 < x1 ≤ tile width, 0 ≤ y0 < y1 ≤
    // tile height.
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    Cut cut = Cut::None;
    // The first slanted line, (ax, ay)–(bx, by); unused for a box.
    int32_t ax = 0, ay = 0, bx = 0, by = 0;
    // A one-way shape stops bodies only from above (semantics §9, §12).
    bool one_way = false;
    // The further slanted lines of a convex polygon with more than one
    // slanted edge on its kept side, left to right after the first: the
    // shape keeps what lies on the kept side of every line. None for a
    // box or a ramp.
    uint8_t n_more = 0;
    std::array<Slant, kMaxShapeSlants - 1> more{};
    // The underside's slanted lines, left to right, of a floor shape whose
    // polygon is slanted below too (a diamond): it keeps what also lies
    // above every one of them. None for every other shape.
    uint8_t n_under = 0;
    std::array<Slant, kMaxShapeSlants> under{};

    bool ramp() const { return cut != Cut::None; }
    int slants() const { return cut == Cut::None ? 0 : 1 + n_more; }
    // Slanted both on its top and on its underside.
    bool two_sided() const { return n_under > 0; }
    // The i-th slanted line, 0 ≤ i < slants(), left to right.
    Slant slant(int i) const { return i == 0 ? Slant{ax, ay, bx, by} : more[static_cast<size_t>(i - 1)]; }
    // The greatest |dy/dx| of its slants: 1 for 45°, 0.5 for 1:2, 2 for 2:1;
    // 0 for a box.
    double steepness() const;
    // Where along x (tile px) a floor shape's top is highest and a ceiling
    // shape's bottom lowest (semantics §12, "apex"): x1 when every slant
    // climbs that way rightwards, x0 when every one climbs leftwards, else
    // the right end of the last slant that climbs rightwards.
    int32_t apex() const;
    // Where a two-sided shape's bottom is lowest, as apex() says for a
    // ceiling shape's slants, read from its underside's; apex() for a
    // ceiling shape, x0 for any other.
    int32_t under_apex() const;
    bool operator==(const CellShape&) const = default;
};

// One slanted line's numbers as doubles.
struct LineGeometry {
    double ax = 0, ay = 0;  // its first point
    double dx = 0, dy = 0;  // its run and rise
    // 1/dx when dx is a power of two, so multiplying by it gives the very
    // bits dividing by dx does (a division's latency, in every ramp height
    // a rule asks for); 0 for any other run.
    double inv_dx = 0;

    static LineGeometry of(Slant s) {
        const auto d = [](int32_t v) { return static_cast<double>(v); };
        const int32_t run = s.bx - s.ax;
        const double inv = run > 0 && (run & (run - 1)) == 0 ? 1.0 / run : 0.0;
        return {d(s.ax), d(s.ay), d(run), d(s.by - s.ay), inv};
    }
};

// A shape's numbers as doubles, converted once when a grid takes the shape
// (TileGrid::set_shape) rather than each time a rule places it in a cell:
// the rules place a shape several times per body per frame.
struct ShapeGeometry {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the box
    LineGeometry line;                      // the first slant
    double apex = 0;                        // CellShape::apex()
    int n_more = 0;                         // further slants, for a polygon
    std::array<LineGeometry, kMaxShapeSlants - 1> more{};
    double under_apex = 0;                  // CellShape::under_apex()
    int n_under = 0;                        // the underside's slants, for a two-sided shape
    std::array<LineGeometry, kMaxShapeSlants> under{};

    static ShapeGeometry of(const CellShape& s) {
        const auto d = [](int32_t v) { return static_cast<double>(v); };
        ShapeGeometry g{d(s.x0), d(s.y0), d(s.x1), d(s.y1), LineGeometry::of(s.slant(0)), d(s.apex()), s.n_more, {},
                        d(s.under_apex()), s.n_under, {}};
        for (int i = 0; i < s.n_more; ++i) g.more[static_cast<size_t>(i)] = LineGeometry::of(s.more[static_cast<size_t>(i)]);
        for (int i = 0; i < s.n_under; ++i)
            g.under[static_cast<size_t>(i)] = LineGeometry::of(s.under[static_cast<size_t>(i)]);
        return g;
    }
};

}  // namespace ds
