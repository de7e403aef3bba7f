// SPDX-License-Identifier: MIT
// The room a body takes up over a frame, and whether two such rooms are
// close enough for one body's frame to read the other: what resting groups
// (settle.hpp) are made of, and what push-apart records when asked
// (ContactScratch::rooms).
#pragma once
#include <algorithm>

#include "body.hpp"
#include "constants.hpp"

namespace ds {

// The hull of a body's boxes over a frame: at its start, at the start of
// each sub-frame, before each push-apart, after every pair it met in the
// push-apart pass, and at its end.
struct Extent {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    static Extent of(const Body& b) { return {b.x.v, b.y.v, b.x.v + b.w.v, b.y.v + b.h.v}; }
    void add(const Body& b) {
        x0 = std::min(x0, b.x.v), y0 = std::min(y0, b.y.v);
        x1 = std::max(x1, b.x.v + b.w.v), y1 = std::max(y1, b.y.v + b.h.v);
    }
    // Whether two bodies whose rooms these are may read each other in a
    // frame. Every read of another body needs the two boxes to overlap
    // strictly along x (push-apart, ground detection, the resting check;
    // semantics §4), computed from the very sums the rooms hold: rooms that
    // only touch along x cannot have held such boxes, so stacks 1 px apart
    // are apart. Along y ground detection reads a supporter up to
    // kOnSolidTolerance below a body's feet; one pixel more keeps that test
    // clear of rounding.
    static constexpr double kReachX = 0;
    static constexpr double kReachY = kOnSolidTolerance + 1;
    bool reaches(const Extent& o) const {
        return x0 - kReachX < o.x1 && o.x0 < x1 + kReachX && y0 - kReachY <= o.y1 && o.y0 <= y1 + kReachY;
    }
};

}  // namespace ds
