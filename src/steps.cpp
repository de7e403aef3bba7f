#include "steps.hpp"

namespace ds {

bool apply_acceleration(Body& b) {
    if (!b.gravity || b.skips(kSkipAcceleration)) return false;
    b.vy = b.vy + b.ay;
    if (b.ay.v != 0) b.ay = Num::integer(0);
    return true;
}

bool apply_gravity(Body& b, SubStep s) {
    if (!b.gravity || b.skips(kSkipGravity)) return false;
    b.vy = b.vy + s.share(Num::integer(kGravity));
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
