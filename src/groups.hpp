// SPDX-License-Identifier: MIT
// Rigid groups: members follow their group's origin entity.
#pragma once
#include <span>

#include "body.hpp"
#include "export.hpp"

namespace ds {

// For each group tag, the first body with group_origin is the origin; every
// other body of that group is placed at origin + (local_x, local_y).
// Allocates its scratch per call; a Frame keeps its own
// (detail/group_scratch.hpp).
DOWNSTROKE_API void sync_groups(std::span<Body> bodies);

}  // namespace ds
