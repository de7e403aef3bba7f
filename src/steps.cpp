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

// v moved toward 0 by d (> 0), never past it: a velocity within d of 0
// stops, exact only when both were (a still one is left as it is).
Num drag_toward_zero(Num v, Num d) {
    if (v.v > d.v) return v - d;
    if (v.v < -d.v) return v + d;
    if (v.v == 0) return v;
    return {0.0, v.exact && d.exact};
}

// v with its magnitude at most cap: ±cap (the cap's exactness) past it. A
// zero cap is exact (NonNegNum), and an exact zero is +0.0, never −0.0.
Num clamp_speed(Num v, SpeedCap cap) {
    const Num c = cap.num();
    if (v.v > c.v) return c;
    if (v.v < -c.v) return c.exact ? Num::integer(0.0 - c.v) : -c;
    return v;
}

}  // namespace

bool apply_speed_limits(Body& b, SubStep s) {
    if (!b.limits_speed() || b.skips(kSkipSpeedLimits)) return false;
    if (!b.drag.absent()) {
        const Num d = s.share(b.drag.num());
        b.vx = drag_toward_zero(b.vx, d);
        b.vy = drag_toward_zero(b.vy, d);
    }
    b.vx = clamp_speed(b.vx, b.max_vx);
    b.vy = clamp_speed(b.vy, b.max_vy);
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
