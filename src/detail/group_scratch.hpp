// SPDX-License-Identifier: MIT
// sync_groups with scratch the caller keeps, so a warm Frame does not
// allocate: the origins found in the last call.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "../groups.hpp"

namespace ds {

struct GroupScratch {
    std::vector<std::pair<int64_t, size_t>> origins;  // (group tag, origin index)
};
void sync_groups(GroupScratch& scratch, std::span<Body> bodies);

}  // namespace ds
