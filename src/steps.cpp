#include "steps.hpp"

namespace ds {

bool apply_acceleration(Body& b) {
    if (!b.gravity || b.skips(kSkipAcceleration)) return false;
    b.vy = b.vy + b.ay;
    if (b.ay.v != 0) b.ay = Num::integer(0);
    return true;
}

bool apply_gravity(Body& b) {
    if (!b.gravity || b.skips(kSkipGravity)) return false;
    b.vy = b.vy + Num::integer(kGravity);
    return true;
}

bool apply_velocity_x(Body& b) {
    if (b.skips(kSkipVelocityX)) return false;
    b.x = b.x + b.vx;
    return true;
}

bool apply_velocity_y(Body& b) {
    if (b.skips(kSkipVelocityY)) return false;
    b.y = b.y + b.vy;
    return true;
}

bool apply_velocity(Body& b) {
    const bool x = apply_velocity_x(b);
    const bool y = apply_velocity_y(b);
    return x || y;
}

}  // namespace ds
