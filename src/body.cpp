// SPDX-License-Identifier: MIT
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
    {"tweens", kSkipTweens},              {"carry", kSkipCarry},
    {"speed-limits", kSkipSpeedLimits},
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
#define DS_FIELD(Name, type, member, keyword, rule) \
    if (!same_field(before.member, after.member)) mask |= kField##Name;
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
    return mask;
}

}  // namespace ds
