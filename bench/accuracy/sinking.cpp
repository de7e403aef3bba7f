// SPDX-License-Identifier: MIT
#include "accuracy/sinking.hpp"

#include <algorithm>

#include "frame.hpp"
#include "speed/paths.hpp"
#include "speed/scenes.hpp"

namespace bench::accuracy {

namespace {

double overlap(double p1, double s1, double p2, double s2) {
    return std::min(p1 + s1, p2 + s2) - std::max(p1, p2);
}

// The deepest a body sits in one whole solid cell: per cell, the smaller
// axis overlap (as Penetration by scene measures it).
double depth_in_tiles(const ds::Body& b, const ds::TileGrid& g) {
    const ds::CellRange cols = g.clip_cols(ds::cells_of(b.x, b.w, g.tile_width()));
    const ds::CellRange rows = g.clip_rows(ds::cells_of(b.y, b.h, g.tile_height()));
    const double tw = g.tile_width(), th = g.tile_height();
    double deepest = 0;
    for (int64_t r = rows.first; r <= rows.last; ++r)
        for (int64_t c = cols.first; c <= cols.last; ++c)
            if (g.solid(c, r))
                deepest = std::max(deepest, std::min(overlap(b.x.v, b.w.v, static_cast<double>(c) * tw, tw),
                                                     overlap(b.y.v, b.h.v, static_cast<double>(r) * th, th)));
    return deepest;
}

}  // namespace

Sinking measure_sinking(const std::string& name, int n, ds::PushRule rule, long frames) {
    const Scene scene = make_scene(name, n);
    ds::TileGrid grid(scene.cols, scene.rows, scene.tile, scene.tile, scene.solid);
    add_shapes(grid, scene);
    ds::World world;
    world.grid = &grid;
    world.bodies = to_bodies(scene);
    std::vector<int64_t> rvx, rvy;
    for (const SceneBody& b : scene.bodies) rvx.push_back(b.rvx), rvy.push_back(b.rvy);
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
