// Rigid groups: members follow their group's origin entity.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "body.hpp"

namespace ds {

// For each group tag, the first body with group_origin is the origin; every
// other body of that group is placed at origin + (local_x, local_y).
// `scratch` keeps the origins between calls (a Frame owns one, so a warm
// frame does not allocate); the one-argument form uses its own.
struct GroupScratch {
    std::vector<std::pair<int64_t, size_t>> origins;  // (group tag, origin index)
};
void sync_groups(GroupScratch& scratch, std::span<Body> bodies);
void sync_groups(std::span<Body> bodies);

}  // namespace ds
