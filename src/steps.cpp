// SPDX-License-Identifier: MIT
#include "steps.hpp"

namespace ds {

bool apply_acceleration(Body& b) {
    if (!b.gravity || b.skips(kSkipAcceleration)) return false;
    b.vy = b.vy + b.ay;
    if (b.ay.v != 0) b.ay = Num::integer(0);
    return true;
}

bool apply_gravity(Body& b, SubStep s, Num g) {
    if (!b.gravity || b.skips(kSkipGravity)) return false;
    // At the default scale the seed's sum, exactly: no product to round.
    b.vy = b.vy + s.share(b.gravity_scale.absent() ? g : g * b.gravity_scale.n);
    return true;
}

namespace {

// The helpers take and give a velocity as its two parts, read and written
// member by member: the step before (gravity, a tile step) stored the
// exactness as a byte, and loading the whole Num as one 16-byte value
// straight after stalls on that store (no store-to-load forwarding from a
// byte to a wider load), which cost a falling body with limits a fifth more.

// v moved toward 0 by d (> 0), never past it: a velocity within d of 0
// stops, exact only when both were (a still one is left as it is).
inline void drag_toward_zero(double& v, bool& exact, double d, bool d_exact) {
    if (v > d) v -= d;
    else if (v < -d) v += d;
    else if (v != 0) v = 0.0;
    else return;
    exact = exact && d_exact;
}

// v with its magnitude at most cap: ±cap (the cap's exactness) past it. A
// zero cap is exact (NonNegNum), and an exact zero is +0.0, never −0.0.
inline void clamp_speed(double& v, bool& exact, SpeedCap cap) {
    const double c = cap.value();
    if (v > c) {
        v = c;
        exact = cap.exact();
    } else if (v < -c) {
        v = cap.exact() ? 0.0 - c : -c;
        exact = cap.exact();
    }
}

}  // namespace

bool apply_speed_limits(Body& b, SubStep s) {
    if (!b.limits_speed() || b.skips(kSkipSpeedLimits)) return false;
    double vx = b.vx.v, vy = b.vy.v;
    bool vx_exact = b.vx.exact, vy_exact = b.vy.exact;
    if (!b.drag.absent()) {
        const Num d = s.share(b.drag.num());
        drag_toward_zero(vx, vx_exact, d.v, d.exact);
        drag_toward_zero(vy, vy_exact, d.v, d.exact);
    }
    clamp_speed(vx, vx_exact, b.max_vx);
    clamp_speed(vy, vy_exact, b.max_vy);
    b.vx.v = vx;
    b.vx.exact = vx_exact;
    b.vy.v = vy;
    b.vy.exact = vy_exact;
    return true;
}

namespace {

// A sub-frame leaves a still body's coordinate as it is (exact stays exact);
// the whole frame adds even a zero, as the seed's step does.
void advance(Num& pos, Num vel, SubStep s) {
    if (!s.whole() && vel.v == 0) return;
    pos = pos + s.share(vel);
}

}  // namespace

bool apply_velocity_x(Body& b, SubStep s) {
    if (b.skips(kSkipVelocityX)) return false;
    advance(b.x, b.vx, s);
    return true;
}

bool apply_velocity_y(Body& b, SubStep s) {
    if (b.skips(kSkipVelocityY)) return false;
    advance(b.y, b.vy, s);
    return true;
}

bool apply_velocity(Body& b) {
    const bool x = apply_velocity_x(b);
    const bool y = apply_velocity_y(b);
    return x || y;
}

}  // namespace ds
