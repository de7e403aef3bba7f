// SPDX-License-Identifier: MIT
// The native path: the scene as a ds::World, one ds::Frame::step per frame;
// and the bare loop over the same body array.
#include <vector>

#include "common/timing.hpp"
#include "frame.hpp"
#include "tilemap/tile_shapes.hpp"
#include "speed/paths.hpp"

namespace bench {

namespace {

ds::Num exact(int64_t v) { return ds::Num::integer(static_cast<double>(v)); }

}  // namespace

std::vector<ds::Body> to_bodies(const Scene& s) {
    std::vector<ds::Body> out;
    out.reserve(s.bodies.size());
    for (const SceneBody& sb : s.bodies) {
        ds::Body b;
        b.x = exact(sb.x);
        b.y = exact(sb.y);
        b.w = exact(sb.w);
        b.h = exact(sb.h);
        b.vx = exact(sb.vx);
        b.vy = exact(sb.vy);
        b.gravity = sb.gravity;
        b.solid = sb.solid;
        b.immovable = sb.immovable;
        b.on_ground = sb.on_ground;
        if (sb.enemy) {  // index 1: enemy; it collides with default (bit 0) and enemy (bit 1)
            b.category.index = 1;
            b.collides_with.bits = 3;
        }
        if (sb.target) {  // an enemy that also collides with shot (bit 2)
            b.category.index = 1;
            b.collides_with.bits = 7;
        }
        if (sb.shot) {  // index 2: shot; it collides with enemy
            b.category.index = 2;
            b.collides_with.bits = 2;
        }
        if (sb.bounce) b.bounce = ds::UnitNum::of(exact(1));
        b.contacts = sb.contacts;
        b.sensor = sb.sensor;
        if (sb.knobs) {
            b.gravity_scale.n = exact(2);
            b.drag = ds::DragNum::of(exact(1));
            b.max_vx = ds::SpeedCap::of(exact(4));
            b.max_vy = ds::SpeedCap::of(exact(64));
        }
        out.push_back(b);
    }
    return out;
}

// The untimed bounce update, as (bench driver) does it on plists: an axis
// whose velocity a collision zeroed turns round.
void bounce(std::vector<ds::Body>& bodies, std::vector<int64_t>& rvx, std::vector<int64_t>& rvy) {
    for (size_t i = 0; i < bodies.size(); ++i) {
        ds::Body& b = bodies[i];
        if (rvx[i] != 0 && b.vx.exact && b.vx.v == 0) {
            rvx[i] = -rvx[i];
            b.vx = exact(rvx[i]);
        }
        if (rvy[i] != 0 && b.vy.exact && b.vy.v == 0) {
            rvy[i] = -rvy[i];
            b.vy = exact(rvy[i]);
        }
    }
}

// The scene's shaped cells, read as the map loader reads a collision polygon.
void add_shapes(ds::TileGrid& grid, const Scene& scene) {
    for (const SceneShape& sh : scene.shapes) {
        ds::MapObject o;
        o.shape = ds::ObjectShape::Polygon;
        for (const auto& [x, y] : sh.polygon) o.points.push_back({static_cast<double>(x), static_cast<double>(y)});
        const ds::TileSolidPart part = ds::tile_solid_part({o}, scene.tile, scene.tile, 0);
        if (part.whole) grid.set_solid(sh.col, sh.row, true);
        else grid.set_shape(sh.col, sh.row, part.shape);
    }
}

NativeScene::NativeScene(const Scene& scene)
    : grid(scene.cols, scene.rows, scene.tile, scene.tile, scene.solid) {
    add_shapes(grid, scene);
    world.grid = &grid;
    world.bodies = to_bodies(scene);
    for (const SceneBody& b : scene.bodies) rvx.push_back(b.rvx), rvy.push_back(b.rvy);
}

PathResult run_native(const Scene& scene, const RunConfig& cfg) {
    PathResult r;
    const int64_t t_setup = now_ns();
    NativeScene native(scene);
    auto& [grid, world, rvx, rvy] = native;
    ds::Frame frame;
    ds::FrameOptions opts;  // swept, dt = 1000/60 ms
    opts.resting_contacts = scene.resting_contacts;
    r.setup_ms = static_cast<double>(now_ns() - t_setup) / 1e6;
    FrameGuard guard(cfg.max_frame_ms, cfg.budget_ms);
    r.frame_ms.reserve(static_cast<size_t>(cfg.frames));
    for (int i = 0; i < cfg.warmup + cfg.frames; ++i) {
        const int64_t t0 = now_ns();
        frame.step(world, opts);
        const int64_t t1 = now_ns();
        const double ms = static_cast<double>(t1 - t0) / 1e6;
        if (i >= cfg.warmup) r.frame_ms.push_back(ms);
        r.spent_ms += ms;
        if (scene.bounce) bounce(world.bodies, rvx, rvy);
        if (!guard.keep_going(ms, static_cast<int>(r.frame_ms.size()))) break;
    }
    r.skipped = guard.skip_reason();
    r.checksum = 0;
    for (size_t i = 0; i < world.bodies.size(); ++i)
        if (!scene.bodies[i].immovable) r.checksum += world.bodies[i].x.v + 3 * world.bodies[i].y.v;
    return r;
}

PathResult run_bare(const Scene& scene, const RunConfig& cfg) {
    PathResult r;
    std::vector<ds::Body> bodies = to_bodies(scene);
    auto pass = [&] {
        for (ds::Body& b : bodies) {
            b.x = b.x + b.vx;
            b.y = b.y + b.vy;
        }
        asm volatile("" : : "r"(bodies.data()) : "memory");  // keep every frame's writes
    };
    for (int i = 0; i < cfg.warmup + cfg.frames; ++i) {
        const int64_t t0 = now_ns();
        pass();
        const int64_t t1 = now_ns();
        if (i >= cfg.warmup) r.frame_ms.push_back(static_cast<double>(t1 - t0) / 1e6);
        r.spent_ms += static_cast<double>(t1 - t0) / 1e6;
    }
    return r;
}

}  // namespace bench
