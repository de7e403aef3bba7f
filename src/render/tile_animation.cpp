// SPDX-License-Identifier: MIT
#include "tile_animation.hpp"

#include <algorithm>
#include <cmath>

namespace ds::render {

uint32_t animation_frame(const std::vector<AnimationFrame>& frames, double time_ms, uint32_t still) {
    double cycle = 0;
    for (const AnimationFrame& f : frames) cycle += std::max(f.duration_ms, 0);
    if (!(cycle > 0) || !std::isfinite(time_ms)) return still;
    double t = std::fmod(std::max(time_ms, 0.0), cycle);
    for (const AnimationFrame& f : frames) {
        const int d = std::max(f.duration_ms, 0);
        if (t < d) return f.tile_id;
        t -= d;
    }
    return still;  // not reached: t < cycle
}

bool has_animation(const Tileset& ts) {
    return std::any_of(ts.tiles.begin(), ts.tiles.end(),
                       [](const TileInfo& t) { return !t.animation.empty(); });
}

}  // namespace ds::render
