#include "steps.hpp"

namespace ds {

void apply_acceleration(Body& b) {
    if (!b.gravity || b.skips(kSkipAcceleration)) return;
    b.vy = b.vy + b.ay;
    if (b.ay.v != 0) b.ay = Num::integer(0);
}

void apply_gravity(Body& b) {
    if (!b.gravity || b.skips(kSkipGravity)) return;
    b.vy = b.vy + Num::integer(kGravity);
}

void apply_velocity_x(Body& b) {
    if (!b.skips(kSkipVelocityX)) b.x = b.x + b.vx;
}

void apply_velocity_y(Body& b) {
    if (!b.skips(kSkipVelocityY)) b.y = b.y + b.vy;
}

void apply_velocity(Body& b) {
    apply_velocity_x(b);
    apply_velocity_y(b);
}

}  // namespace ds
