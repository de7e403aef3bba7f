// The per-entity motion steps (SPEC §4), each guarded and skippable exactly as
// default-engine-update would apply it. They read and write one body, and
// return whether they applied (false: guarded out or skipped).
#pragma once
#include "body.hpp"

namespace ds {

constexpr double kGravity = 1.0;            // *gravity*, px/frame²
constexpr double kJumpForce = 15.0;         // *jump-force*
constexpr double kOnSolidTolerance = 4.0;   // *on-solid-tolerance*, px and px/frame

// vy += ay, then ay = 0. Needs #:gravity?; skipped by 'acceleration.
bool apply_acceleration(Body& b);
// vy += *gravity*. Needs #:gravity?; skipped by 'gravity.
bool apply_gravity(Body& b);
// x += vx; skipped by 'velocity-x.
bool apply_velocity_x(Body& b);
// y += vy; skipped by 'velocity-y.
bool apply_velocity_y(Body& b);
// The legacy step: both axes, each skippable on its own.
bool apply_velocity(Body& b);

}  // namespace ds
