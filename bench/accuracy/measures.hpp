// SPDX-License-Identifier: MIT
// The errors `downstroke-bench accuracy` measures, each against a truth
// known without the engine: the continuous jump, the wall a projectile must
// not cross, the solids no body may end a frame inside, the start positions
// of bodies at rest.
#pragma once
#include <string>

#include "accuracy/scenes.hpp"

namespace bench::accuracy {

// One way of running the physics: collision mode, sub-frames, resting contacts.
struct Config {
    ds::CollisionMode mode = ds::CollisionMode::Swept;
    int k = 1;
    bool resting = false;

    ds::FrameOptions options() const;
    const char* mode_name() const;  // "discrete" / "swept"
};

// A jump from vy = −15 under gravity 1, against y(t) = y0 + v0·t + ½·g·t².
struct Trajectory {
    int frames = 0;
    double max_error = 0;    // px, the largest |y − y_exact| at a frame end
    int land_frame = -1;     // first frame it is on the floor again (−1: never)
    int land_expected = 0;   // the continuous landing time, rounded up
    int land_error() const { return land_frame < 0 ? 0 : land_frame - land_expected; }
};
Trajectory measure_trajectory(const Config& c, int frames);

// Projectiles at speeds 1..max_speed, every integer phase, at a wall.
struct Tunneling {
    int max_speed = 0;
    long tested = 0;
    long escaped = 0;      // ended beyond the wall
    long lodged = 0;       // ended inside it
    int first_escape = 0;  // the lowest speed anything escaped at (0: none)
    // The highest speed up to which nothing escaped.
    int safe_to() const { return first_escape == 0 ? max_speed : first_escape - 1; }
};
Tunneling measure_tunneling(const Config& c, int max_speed);
// The same against ramps (semantics §12): shots falling onto a 45° and a
// 1:2 floor ramp, rising into a ceiling ramp, flying into a ramp's tall
// side, at 1 … max_speed px/frame from every gap, at two places along it.
Tunneling measure_ramp_tunneling(const Config& c, int max_speed);

}  // namespace bench::accuracy
