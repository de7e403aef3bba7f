// SPDX-License-Identifier: MIT
// One axis of a body — its position, velocity and size along x or along y —
// so a rule written once serves both axes: push-apart's sharing of an overlap
// (contacts.cpp) and the snap-out of solid cells (tiles.cpp).
#pragma once
#include "body.hpp"

namespace ds {

struct BodyAxis {
    Num& pos;
    Num& vel;
    Num size;
    // Twice the centre: keeps centre comparisons exact for integer boxes.
    double centre2() const { return 2 * pos.v + size.v; }
};

inline BodyAxis along_x(Body& b) { return {b.x, b.vx, b.w}; }
inline BodyAxis along_y(Body& b) { return {b.y, b.vy, b.h}; }

}  // namespace ds
