// SPDX-License-Identifier: MIT
#include "interpolate.hpp"

#include <cmath>
#include <unordered_map>

namespace ds::render {

double interpolated(double before, double now, double alpha) {
    if (!(std::fabs(now - before) <= kTeleportPx)) return now;
    return before + alpha * (now - before);
}

namespace {

bool same_body(const EntityView& a, const EntityView& b) { return a.w == b.w && a.h == b.h; }

void move_between(EntityView& now, const EntityView& before, double alpha) {
    if (!(std::fabs(now.x - before.x) <= kTeleportPx && std::fabs(now.y - before.y) <= kTeleportPx)) return;
    now.x = before.x + alpha * (now.x - before.x);
    now.y = before.y + alpha * (now.y - before.y);
}

}  // namespace

void interpolate_views(std::span<EntityView> now, std::span<const int64_t> now_ids,
                       std::span<const EntityView> before, std::span<const int64_t> before_ids, double alpha) {
    std::unordered_map<int64_t, size_t> by_id;  // built only when a list changed order
    bool indexed = false;
    for (size_t i = 0; i < now.size(); ++i) {
        if (i < before.size() && now_ids[i] == before_ids[i] && same_body(now[i], before[i])) {
            move_between(now[i], before[i], alpha);
            continue;
        }
        if (now_ids[i] == 0) continue;  // appeared, or no way to tell who it was
        if (!indexed) {
            for (size_t k = 0; k < before.size(); ++k)
                if (before_ids[k] != 0) by_id.emplace(before_ids[k], k);
            indexed = true;
        }
        const auto it = by_id.find(now_ids[i]);
        if (it != by_id.end()) move_between(now[i], before[it->second], alpha);
    }
}

}  // namespace ds::render
