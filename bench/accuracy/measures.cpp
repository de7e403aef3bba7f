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

}  // namespace bench::accuracy
