// SPDX-License-Identifier: MIT
// Settling: a whole frame leaves alone the bodies it cannot change, as Box2D
// lets bodies sleep. Both whole-frame paths use this unit — ds::Frame::step
// (through SettleTracker) and the bindings' step-scene (through Settling) —
// and its words:
//
// - A body *settles* in a frame when the frame leaves it as it entered, it
//   has no tween, and it depends on no other body (depends_on_others: it does
//   not push or get pushed, follows no group, and looks for no supporter
//   while any exist).
// - A settled body is *asleep* in the next frame, which no step visits it in,
//   when it enters that frame *as left* (as the last frame left it), still has
//   no tween and still depends on nobody, and the frame runs under the same
//   *conditions*: the same map, known by its revision (TileGrid::revision),
//   and the same physics options. Every other body is *awake*: stepped.
//   Under other conditions every settled mark is dropped.
// - A body *can settle* when it has no speed and depends on nobody; the
//   World path counts those to decide whether tracking pays.
//
// The rules hold because a body that depends on nobody is moved only by its
// own fields, its tween, the map and the options: when none changed, the
// frame does what it did last time, which was nothing.
#pragma once
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

#include "body.hpp"
#include "frame_options.hpp"
#include "tile_grid.hpp"
#include "export.hpp"

namespace ds {

// Whether a body's frame can depend on other bodies: it pushes or is pushed
// (solid, not a ghost), follows a group, or — when any supporters exist —
// looks for one under its feet.
inline bool depends_on_others(const Body& b, bool supporters_exist) {
    // A contact body's report names other bodies, and a sensor's pairs do:
    // neither ever sleeps.
    return b.collides() || b.group != 0 || b.contacts || b.sensor ||
           (supporters_exist && b.gravity && !b.skips(kSkipOnSolid));
}
// Whether any body collides (Body::collides): then ground detection has
// supporters to look for.
DOWNSTROKE_API bool any_collider(std::span<const Body> bodies);
// No speed, and depending on nobody: a body that can settle.
inline bool can_settle(const Body& b, bool colliders) {
    return b.vx.v == 0 && b.vy.v == 0 && !depends_on_others(b, colliders);
}

// What every settled body assumes.
struct SettleConditions {
    uint64_t map_revision = 0;  // TileGrid::revision, 0 for no map
    FrameOptions physics;       // only same_physics counts

    static SettleConditions of(const TileGrid* grid, const FrameOptions& opts) { return {revision_of(grid), opts}; }
    bool same(const SettleConditions& o) const {
        return map_revision == o.map_revision && physics.same_physics(o.physics);
    }
};

// The settled mark of each body (by position) and a frame's plan. A frame:
// begin(), then plan() for each body (or propose() for each, then confirm()
// for each once it is known whether any body collides), step every body not
// asleep(), then settle() for each body stepped.
class DOWNSTROKE_API Settling {
public:
    // Starts a frame of n bodies under `now`. Returns whether the conditions
    // are the last frame's; when they are not, every settled mark is dropped
    // and no body is asleep. Marks past n are kept (for a list that grows
    // back: a mark always needs the body to come back as left).
    bool begin(size_t n, const SettleConditions& now);
    // Whether the last frame's settled bodies would sleep under `now`.
    bool holds(const SettleConditions& now) const { return last_ && last_->same(now); }

    // Plans body i: asleep when it settled, enters as left, has no tween and
    // depends on nobody (`colliders`: whether any body collides this frame).
    bool plan(size_t i, bool as_left, bool has_tween, const Body& b, bool colliders) {
        propose(i, as_left, has_tween, b);
        return confirm(i, colliders);
    }
    // plan() in two halves, for a caller that learns `colliders` in the very
    // sweep it plans in: everything but the colliders, then the colliders.
    void propose(size_t i, bool as_left, bool has_tween, const Body& b) {
        if (!same_) return;
        const bool may = as_left && settled_[i] && !has_tween && !depends_on_others(b, false);
        asleep_[i] = static_cast<uint8_t>(may | (depends_on_others(b, true) << 1));
    }
    bool confirm(size_t i, bool colliders) {
        const uint8_t v = asleep_[i];
        asleep_[i] = (v & 1) && !(colliders && (v & 2));
        return asleep_[i];
    }
    // This frame's plan, by body: 1 asleep, 0 awake.
    std::span<const uint8_t> asleep() const { return asleep_; }

    // After the frame, for a body it stepped (an asleep one stays settled):
    // whether it settled. `unchanged`: the frame left it as it entered.
    bool settle(size_t i, bool unchanged, bool has_tween, const Body& b, bool colliders) {
        settled_[i] = unchanged && !has_tween && !depends_on_others(b, colliders);
        return settled_[i];
    }
    bool settled(size_t i) const { return i < settled_.size() && settled_[i]; }
    // Body i is no longer the body its mark was made for.
    void forget(size_t i) {
        if (i < settled_.size()) settled_[i] = 0;
    }
    // Nothing is settled.
    void forget_all() { settled_.assign(settled_.size(), 0); }

private:
    std::optional<SettleConditions> last_;  // none before the first frame
    bool same_ = false;
    std::vector<uint8_t> settled_;  // by body
    std::vector<uint8_t> asleep_;   // by body, this frame (between propose and confirm: two bits)
};

// Settling for a caller that holds only bodies (ds::Frame::step over a
// World): it tells a body enters a frame as left by comparing it byte for
// byte with a copy of what the last frame left. That costs about half of
// stepping the body, so it pays only while at least half of the bodies can
// settle: the tracker tracks while they could after the last frame, and
// otherwise counts the bodies that can settle as the frame steps them.
class DOWNSTROKE_API SettleTracker {
public:
    // Whether this frame tracks (decided by the last end_frame).
    bool tracking() const { return tracking_; }

    // Tracking: starts a frame of n bodies under `now` (as Settling::begin;
    // a different number of bodies is a new scene: nothing settled). Then
    // mark_tween() for each body with a tween, propose() for each body,
    // confirm() for each; after the frame settle() for each body stepped.
    bool begin(size_t n, const SettleConditions& now);
    void mark_tween(size_t i) {
        if (i < has_tween_.size()) has_tween_[i] = 1;
    }
    void propose(size_t i, const Body& b) {
        if (!same_) return;
        as_left_[i] = std::memcmp(&b, &left_[i], sizeof(Body)) == 0;
        marks_.propose(i, as_left_[i], has_tween_[i], b);
    }
    bool confirm(size_t i, bool colliders) { return marks_.confirm(i, colliders); }
    void settle(size_t i, const Body& b, bool colliders);

    // Not tracking: forgets every copy (nothing is settled), and counts.
    void skip();
    bool counting() const { return counting_; }
    void count(const Body& b, bool colliders) { counted_ += can_settle(b, colliders); }

    // Every frame, at its end: whether the next one tracks.
    void end_frame(size_t n);

private:
    Settling marks_;
    std::vector<Body> left_;  // by body: as the last frame left it
    std::vector<uint8_t> as_left_, has_tween_;  // by body, this frame
    std::vector<uint8_t> can_settle_;           // by body, after the last frame
    size_t can_settle_count_ = 0;
    size_t counted_ = 0;  // this frame, when not tracking
    bool same_ = false;  // this frame: the last one's bodies and conditions
    bool tracking_ = true, counting_ = false;
};

}  // namespace ds
