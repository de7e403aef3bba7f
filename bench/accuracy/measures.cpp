// SPDX-License-Identifier: MIT
#include <memory>
#include "tiles.hpp"
#include "accuracy/measures.hpp"

#include <cmath>

namespace bench::accuracy {

ds::FrameOptions Config::options() const {
    ds::FrameOptions o;
    o.mode = mode;
    o.substeps = k;
    o.resting_contacts = resting;
    return o;
}

const char* Config::mode_name() const { return mode == ds::CollisionMode::Swept ? "swept" : "discrete"; }

namespace {

double exact_y(double y0, double t) { return y0 + kJumpSpeed * t + 0.5 * ds::kGravity * t * t; }

int landing_frame(const Config& c, int limit) {
    const Setup s = jump_floor();
    ds::World w = s.world();
    ds::Frame frame;
    for (int t = 1; t <= limit; ++t) {
        frame.step(w, c.options());
        if (w.bodies[0].on_ground) return t;
    }
    return -1;
}

}  // namespace

Trajectory measure_trajectory(const Config& c, int frames) {
    Trajectory r;
    r.frames = frames;
    const Setup s = jump_free();
    ds::World w = s.world();
    const double y0 = w.bodies[0].y.v;
    ds::Frame frame;
    for (int t = 1; t <= frames; ++t) {
        frame.step(w, c.options());
        r.max_error = std::max(r.max_error, std::fabs(w.bodies[0].y.v - exact_y(y0, t)));
    }
    // The continuous body is back on the floor when y(t) = y0 again.
    r.land_expected = static_cast<int>(std::ceil(-2 * kJumpSpeed / ds::kGravity));
    r.land_frame = landing_frame(c, 4 * r.land_expected);
    return r;
}

Tunneling measure_tunneling(const Config& c, int max_speed) {
    Tunneling r;
    r.max_speed = max_speed;
    const Setup s = tunnel_lane(max_speed);
    const std::vector<int> speeds = tunnel_speeds(max_speed);
    ds::World w = s.world();
    ds::Frame frame;
    // Each projectile starts at most v px short of the wall: within two
    // frames it has been stopped or is past.
    for (int t = 0; t < 3; ++t) frame.step(w, c.options());
    const double wall = tunnel_wall_x();
    for (size_t i = 0; i < w.bodies.size(); ++i) {
        const ds::Body& b = w.bodies[i];
        ++r.tested;
        if (b.x.v >= wall + kTile) {
            ++r.escaped;
            if (r.first_escape == 0) r.first_escape = speeds[i];
        } else if (b.x.v + b.w.v > wall) {
            ++r.lodged;
        }
    }
    return r;
}

namespace {

// One ramp cell at column 2, row 1 (x 32–48, y 16–32) of an otherwise empty
// 5 × 3 grid, and how shots reach it.
struct RampLane {
    const char* name;
    ds::CellShape shape;
    int vx_sign, vy_sign;  // the direction shots fly in
};

ds::CellShape ramp_shape(int y0, ds::Cut cut, int ay, int by) {
    ds::CellShape s;
    s.x0 = 0, s.y0 = y0, s.x1 = kTile, s.y1 = kTile, s.cut = cut;
    s.ax = 0, s.ay = ay, s.bx = kTile, s.by = by;
    return s;
}

}  // namespace

Tunneling measure_ramp_tunneling(const Config& c, int max_speed) {
    // Falling onto a 45° and a 1:2 floor ramp, rising into a 45° ceiling
    // ramp, and flying left into a 45° ramp's tall side below its slant.
    const RampLane lanes[] = {
        {"down onto 45°", ramp_shape(0, ds::Cut::Floor, 16, 0), 0, 1},
        {"down onto 1:2", ramp_shape(8, ds::Cut::Floor, 16, 8), 0, 1},
        {"up into a ceiling", ramp_shape(0, ds::Cut::Ceiling, 0, 16), 0, -1},
        {"left into a side", ramp_shape(0, ds::Cut::Floor, 16, 0), -1, 0},
    };
    Tunneling r;
    r.max_speed = max_speed;
    constexpr double kCellX = 2 * kTile, kCellY = kTile;
    const auto exact = [](double v) { return ds::Num::integer(v); };
    for (const RampLane& lane : lanes) {
        auto grid = std::make_shared<ds::TileGrid>(5, 3, kTile, kTile, std::vector<uint8_t>(15, 0));
        grid->set_shape(2, 1, lane.shape);
        ds::World w;
        w.grid = grid.get();
        std::vector<int> speeds;
        for (int v = 1; v <= max_speed; ++v)
            for (int d = 0; d < v; ++d)
                for (const double across : {2.0, 7.0}) {  // two places along the ramp
                    ds::Body b;
                    b.w = b.h = exact(8);
                    if (lane.vy_sign > 0) b.x = exact(kCellX + across), b.y = exact(kCellY - 8 - 1 - d);
                    if (lane.vy_sign < 0) b.x = exact(kCellX + across), b.y = exact(kCellY + kTile + 1 + d);
                    if (lane.vx_sign < 0) b.x = exact(kCellX + kTile + 1 + d), b.y = exact(kCellY + across);
                    b.vx = exact(lane.vx_sign * v);
                    b.vy = exact(lane.vy_sign * v);
                    w.bodies.push_back(b);
                    speeds.push_back(v);
                }
        ds::Frame frame;
        for (int t = 0; t < kTile + 3; ++t) frame.step(w, c.options());
        for (size_t i = 0; i < w.bodies.size(); ++i) {
            const ds::Body& b = w.bodies[i];
            ++r.tested;
            const bool past = lane.vy_sign > 0   ? b.y.v >= kCellY + kTile
                              : lane.vy_sign < 0 ? b.y.v + b.h.v <= kCellY
                                                 : b.x.v + b.w.v <= kCellX;
            if (past) {
                ++r.escaped;
                if (r.first_escape == 0 || speeds[i] < r.first_escape) r.first_escape = speeds[i];
            } else if (ds::overlaps_solid(b, *grid)) {
                ++r.lodged;
            }
        }
    }
    return r;
}

}  // namespace bench::accuracy
