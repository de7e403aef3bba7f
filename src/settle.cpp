// SPDX-License-Identifier: MIT
#include "settle.hpp"

#include <algorithm>

namespace ds {

bool any_collider(std::span<const Body> bodies) {
    return std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.collides(); });
}

bool Settling::begin(size_t n, const SettleConditions& now) {
    same_ = holds(now);
    last_ = now;
    if (!same_) forget_all();
    if (settled_.size() < n) settled_.resize(n, 0);
    asleep_.assign(n, 0);
    return same_;
}

void RestingGroups::begin(size_t n, bool keep) {
    if (!keep || group_.size() != n) {
        group_.assign(n, -1);
        groups_ = 0;
    }
    asleep_.assign(groups_, 1);
    wake_.assign(groups_, 0);
    any_wake_ = false;
    if (extent_.size() != n) extent_.resize(n), room_.resize(n);
}

void RestingGroups::allow(bool allowed) {
    if (!allowed) asleep_.assign(groups_, 0);
    any_asleep_ = std::find(asleep_.begin(), asleep_.end(), 1) != asleep_.end();
}

void RestingGroups::forget() {
    group_.assign(group_.size(), -1);
    groups_ = 0;
    asleep_.clear();
    wake_.clear();
    any_asleep_ = any_wake_ = false;
}

void RestingGroups::file_asleep(std::span<const size_t> members) {
    filed_.clear();
    widest_ = 0;
    for (const size_t i : members)
        if (asleep(i)) {
            filed_.push_back({room_[i], group_[i]});
            widest_ = std::max(widest_, room_[i].x1 - room_[i].x0);
        }
    std::sort(filed_.begin(), filed_.end(), [](const Filed& a, const Filed& b) { return a.box.x0 < b.box.x0; });
}

bool RestingGroups::reached(size_t i) {
    // The filed rooms that can reach extent e start no further left than
    // the widest room and the reach before it, and no further right than
    // the reach after it.
    const Extent& e = extent_[i];
    auto it = std::lower_bound(filed_.begin(), filed_.end(), e.x0 - Extent::kReachX - widest_,
                               [](const Filed& f, double x) { return f.box.x0 < x; });
    bool any = false;
    for (; it != filed_.end() && it->box.x0 <= e.x1 + Extent::kReachX; ++it)
        if (const auto g = static_cast<size_t>(it->group); asleep_[g] && !wake_[g] && e.reaches(it->box)) {
            wake_[g] = 1;
            any = true;
        }
    any_wake_ |= any;
    return any;
}

bool RestingGroups::wake_marked() {
    if (!any_wake_) return false;
    for (size_t g = 0; g < groups_; ++g)
        if (wake_[g]) asleep_[g] = 0, wake_[g] = 0;
    any_wake_ = false;
    any_asleep_ = std::find(asleep_.begin(), asleep_.end(), 1) != asleep_.end();
    return true;
}

size_t RestingGroups::find(size_t m) {
    while (parent_[m] != m) {
        parent_[m] = parent_[parent_[m]];
        m = parent_[m];
    }
    return m;
}

void RestingGroups::form(std::span<const Body> bodies, std::span<const size_t> members,
                         std::span<const uint8_t> unchanged) {
    const size_t m = members.size();
    size_t fits = 0;
    ext_.resize(m);
    fit_.resize(m);
    parent_.resize(m);
    order_.resize(m);
    for (size_t k = 0; k < m; ++k) {
        const size_t i = members[k];
        const Body& b = bodies[i];
        // An asleep member's frame would have been its last one again: it
        // keeps that frame's room.
        const bool slept = asleep(i);
        if (!slept) {
            room_[i] = extent_[i];
            room_[i].add(b);
        }
        ext_[k] = room_[i];
        fit_[k] = (slept || unchanged[i]) && may_rest(b);
        fits += fit_[k];
        parent_[k] = static_cast<uint32_t>(k);
        order_[k] = static_cast<uint32_t>(k);
    }
    // Where most colliders moved (a crowd that jitters), the groups the
    // rest could form would mostly be reached: finding them is not worth
    // its sort. Fewer groups only means more bodies stepped.
    group_.assign(bodies.size(), -1);
    groups_ = 0;
    if (fits * kFitShare < m) return;
    std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) { return ext_[a].x0 < ext_[b].x0; });
    // Sweep by x0: every member that starts before one's right edge (and
    // its reach) is tested against it.
    for (size_t a = 0; a < m; ++a) {
        const Extent& e = ext_[order_[a]];
        for (size_t b = a + 1; b < m && ext_[order_[b]].x0 <= e.x1 + Extent::kReachX; ++b)
            if (e.reaches(ext_[order_[b]])) {
                const size_t ra = find(order_[a]), rb = find(order_[b]);
                if (ra != rb) parent_[std::max(ra, rb)] = static_cast<uint32_t>(std::min(ra, rb));
            }
    }
    // A component is a group when every member of it may rest.
    root_fit_.assign(m, 1);
    for (size_t k = 0; k < m; ++k) root_fit_[find(k)] &= fit_[k];
    root_group_.assign(m, -1);
    for (size_t k = 0; k < m; ++k) {
        const size_t r = find(k);
        if (!root_fit_[r]) continue;
        if (root_group_[r] < 0) root_group_[r] = static_cast<int32_t>(groups_++);
        group_[members[k]] = root_group_[r];
    }
}

bool SettleTracker::begin(size_t n, const SettleConditions& now) {
    const bool same_scene = left_.size() == n;
    if (!same_scene) {  // a new scene (or the first frame tracked again): every body is stepped
        left_.assign(n, Body{});
        can_settle_.assign(n, 0);
        can_settle_count_ = 0;
        marks_.forget_all();
    }
    as_left_.assign(n, 0);
    has_tween_.assign(n, 0);
    unchanged_.assign(n, 0);
    counting_ = false;
    same_ = marks_.begin(n, now) && same_scene;
    groups_.begin(n, same_);
    return same_;
}

void SettleTracker::settle(size_t i, const Body& b, bool colliders) {
    // Settled: it entered this frame as the last one left it, and leaves it
    // the same, depending on nobody.
    const bool same_bits = std::memcmp(&left_[i], &b, sizeof(Body)) == 0;
    const bool unchanged = as_left_[i] && (same_bits || differing_fields(left_[i], b) == 0);
    marks_.settle(i, unchanged, has_tween_[i], b, colliders);
    // A group sleeps only on bit-for-bit rest: its members' frames are
    // skipped, not replayed, so even a sign of zero must not differ.
    unchanged_[i] = as_left_[i] && same_bits && !has_tween_[i];
    if (!same_bits) left_[i] = b;
    const uint8_t can = can_sleep(b, colliders);
    can_settle_count_ += can;
    can_settle_count_ -= can_settle_[i];
    can_settle_[i] = can;
}

void SettleTracker::skip() {
    left_.clear();  // no longer known: nothing is settled
    groups_.forget();
    counting_ = true;
    counted_ = 0;
}

void SettleTracker::end_frame(size_t n) {
    const size_t can = tracking_ ? can_settle_count_ : counted_;
    counting_ = false;
    tracking_ = can * 2 >= n;
}

}  // namespace ds
