// SPDX-License-Identifier: MIT
// The solid part of a cell that is not the whole cell (semantics §12): a
// part-tile box, or a ramp — a box cut by one slanted line. Plain data, in
// whole px from the cell's top-left corner, so a grid keeps one small table
// of them and every rule reads the same numbers the reference does.
#pragma once
#include <cstdint>
#include "export.hpp"

namespace ds {

// Which side of the slanted line a ramp keeps.
enum class Cut : int8_t {
    None = 0,      // a part-tile box: the box is the shape
    Floor = 1,     // what lies below the line (y grows down): a ramp to walk on
    Ceiling = -1,  // what lies above it: a ramp to bump into from below
};

struct DOWNSTROKE_API CellShape {
    // The box [x0, x1) × [y0, y1), 0 ≤ x0 < x1 ≤ tile width, 0 ≤ y0 < y1 ≤
    // tile height.
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    Cut cut = Cut::None;
    // The slanted line through (ax, ay) and (bx, by), ax < bx, ay ≠ by; unused
    // for a box.
    int32_t ax = 0, ay = 0, bx = 0, by = 0;
    // A one-way shape stops bodies only from above (semantics §9, §12).
    bool one_way = false;

    bool ramp() const { return cut != Cut::None; }
    // |dy/dx| of the slant: 1 for 45°, 0.5 for 1:2, 2 for 2:1; 0 for a box.
    double steepness() const;
    bool operator==(const CellShape&) const = default;
};

// A shape's numbers as doubles, converted once when a grid takes the shape
// (TileGrid::set_shape) rather than each time a rule places it in a cell:
// the rules place a shape several times per body per frame.
struct ShapeGeometry {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the box
    double ax = 0, ay = 0;                  // the slant's first point
    double dx = 0, dy = 0;                  // its run and rise
    // 1/dx when dx is a power of two, so multiplying by it gives the very
    // bits dividing by dx does (a division's latency, in every ramp height
    // a rule asks for); 0 for any other run.
    double inv_dx = 0;

    static ShapeGeometry of(const CellShape& s) {
        const auto d = [](int32_t v) { return static_cast<double>(v); };
        const int32_t run = s.bx - s.ax;
        const double inv = run > 0 && (run & (run - 1)) == 0 ? 1.0 / run : 0.0;
        return {d(s.x0), d(s.y0), d(s.x1), d(s.y1), d(s.ax), d(s.ay), d(run), d(s.by - s.ay), inv};
    }
};

}  // namespace ds
