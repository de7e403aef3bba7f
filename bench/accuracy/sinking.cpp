// SPDX-License-Identifier: MIT
#include "accuracy/sinking.hpp"

#include <algorithm>

#include "accuracy/depth.hpp"
#include "frame.hpp"
#include "speed/paths.hpp"
#include "speed/scenes.hpp"

namespace bench::accuracy {

Sinking measure_sinking(const std::string& name, int n, ds::PushRule rule, long frames) {
    const Scene scene = make_scene(name, n);
    NativeScene native(scene);
    auto& [grid, world, rvx, rvy] = native;
    ds::FrameOptions opts;  // the speed benchmark's: swept, k = 1
    opts.push = rule;
    Sinking s{name, n, rule, frames};
    std::vector<bool> sunk(world.bodies.size(), false);
    ds::Frame frame;
    for (long f = 1; f <= frames; ++f) {
        frame.step(world, opts);
        if (scene.bounce) bounce(world.bodies, rvx, rvy);
        long now_sunk = 0;
        for (size_t i = 0; i < world.bodies.size(); ++i) {
            if (scene.bodies[i].immovable) continue;
            const double d = depth_in_tiles(world.bodies[i], grid);
            if (d > s.deepest) s.deepest = d, s.deepest_frame = f;
            if (d >= kSunkDepth) {
                ++now_sunk;
                if (!sunk[i]) sunk[i] = true, ++s.sunk;
            }
        }
        if (f == frames) s.sunk_at_end = now_sunk;
    }
    for (const SceneBody& b : scene.bodies) s.movers += b.immovable ? 0 : 1;
    return s;
}

std::vector<std::string> sinking_scenes() { return {"crowd", "rain", "bullets", "platformer"}; }

std::vector<int> sinking_ns(bool quick) {
    if (quick) return {100, 1000};
    return {100, 1000, 10000, 100000};
}

}  // namespace bench::accuracy
