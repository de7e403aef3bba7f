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
    counting_ = false;
    same_ = marks_.begin(n, now) && same_scene;
    return same_;
}

void SettleTracker::settle(size_t i, const Body& b, bool colliders) {
    // Settled: it entered this frame as the last one left it, and leaves it
    // the same, depending on nobody.
    const bool same_bits = std::memcmp(&left_[i], &b, sizeof(Body)) == 0;
    marks_.settle(i, as_left_[i] && (same_bits || differing_fields(left_[i], b) == 0), has_tween_[i], b, colliders);
    if (!same_bits) left_[i] = b;
    const uint8_t can = can_settle(b, colliders);
    can_settle_count_ += can;
    can_settle_count_ -= can_settle_[i];
    can_settle_[i] = can;
}

void SettleTracker::skip() {
    left_.clear();  // no longer known: nothing is settled
    counting_ = true;
    counted_ = 0;
}

void SettleTracker::end_frame(size_t n) {
    const size_t can = tracking_ ? can_settle_count_ : counted_;
    counting_ = false;
    tracking_ = can * 2 >= n;
}

}  // namespace ds
