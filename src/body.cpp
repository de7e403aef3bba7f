#include "body.hpp"

#include <cstring>

namespace ds {

namespace {

struct SkipName {
    const char* name;
    uint16_t bit;
};

constexpr SkipName kSkipNames[] = {
    {"acceleration", kSkipAcceleration},  {"gravity", kSkipGravity},
    {"velocity-x", kSkipVelocityX},       {"velocity-y", kSkipVelocityY},
    {"tile-collisions-x", kSkipTileX},    {"tile-collisions-y", kSkipTileY},
    {"on-solid", kSkipOnSolid},           {"entity-collisions", kSkipEntityCollisions},
    {"tweens", kSkipTweens},
};

}  // namespace

uint16_t skip_bit(const char* name) {
    for (const auto& s : kSkipNames)
        if (std::strcmp(s.name, name) == 0) return s.bit;
    return 0;
}

const char* skip_name(uint16_t bit) {
    for (const auto& s : kSkipNames)
        if (s.bit == bit) return s.name;
    return nullptr;
}

uint32_t changed_fields(const Body& before, const Body& after) {
    // Most bodies of most frames are copies of themselves: bitwise equal.
    if (std::memcmp(&before, &after, sizeof(Body)) == 0) return 0;
    return differing_fields(before, after);
}

uint32_t differing_fields(const Body& before, const Body& after) {
    uint32_t mask = 0;
    if (!same(before.x, after.x)) mask |= kFieldX;
    if (!same(before.y, after.y)) mask |= kFieldY;
    if (!same(before.vx, after.vx)) mask |= kFieldVx;
    if (!same(before.vy, after.vy)) mask |= kFieldVy;
    if (!same(before.ay, after.ay)) mask |= kFieldAy;
    if (before.on_ground != after.on_ground) mask |= kFieldOnGround;
    if (!same(before.w, after.w)) mask |= kFieldWidth;
    if (!same(before.h, after.h)) mask |= kFieldHeight;
    if (!same(before.local_x, after.local_x)) mask |= kFieldLocalX;
    if (!same(before.local_y, after.local_y)) mask |= kFieldLocalY;
    return mask;
}

}  // namespace ds
