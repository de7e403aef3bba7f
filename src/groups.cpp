// SPDX-License-Identifier: MIT
#include "groups.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "detail/group_scratch.hpp"

namespace ds {

void sync_groups(std::span<Body> bodies) {
    GroupScratch scratch;
    sync_groups(scratch, bodies);
}

void sync_groups(GroupScratch& scratch, std::span<Body> bodies) {
    // (group tag, origin index), sorted by tag; the first origin of a tag wins.
    auto& origins = scratch.origins;
    origins.clear();
    for (size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].group != 0 && bodies[i].group_origin) origins.emplace_back(bodies[i].group, i);
    if (origins.empty()) return;
    std::sort(origins.begin(), origins.end());  // by tag, then index: first origin first

    for (size_t i = 0; i < bodies.size(); ++i) {
        Body& m = bodies[i];
        if (m.group == 0) continue;
        auto it = std::lower_bound(origins.begin(), origins.end(), m.group,
                                   [](const auto& o, int64_t tag) { return o.first < tag; });
        if (it == origins.end() || it->first != m.group || it->second == i) continue;
        const Body& o = bodies[it->second];
        m.x = o.x + m.local_x;
        m.y = o.y + m.local_y;
    }
}

}  // namespace ds
