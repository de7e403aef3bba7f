// SPDX-License-Identifier: MIT
// Issue 50's check, at every N: the speed benchmark's scenes (crowd, rain,
// bullets, the platformer) stepped as its native path steps them, under each
// push rule, counting the bodies that end a frame 1 px or more inside a
// solid tile.
#pragma once
#include <string>
#include <vector>

#include "frame_options.hpp"

namespace bench::accuracy {

struct Sinking {
    std::string scene;
    int n = 0;
    ds::PushRule rule = ds::PushRule::Clipped;
    long frames = 0;
    long movers = 0;
    long sunk = 0;          // bodies ≥ kSunkDepth inside a solid tile at some frame's end
    long sunk_at_end = 0;   // … at the last frame's end
    double deepest = 0;     // px, the smaller axis overlap with one cell
    long deepest_frame = -1;
};

// How deep inside a tile counts as sunk: the threshold. Less is
// rounding in a flonum position (a 1:2 ramp's half pixel), not a body in
// the floor.
constexpr double kSunkDepth = 1;

Sinking measure_sinking(const std::string& scene, int n, ds::PushRule rule, long frames);

// The scenes and N of the check; `quick`: N up to 1000.
std::vector<std::string> sinking_scenes();
std::vector<int> sinking_ns(bool quick);

}  // namespace bench::accuracy
