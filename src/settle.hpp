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
//
// Colliders, which do depend on others, sleep in *resting groups* on both
// paths (RestingGroups below, with why that is exact; the bindings keep
// theirs through Frame::step_physics_resting).
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

#include "body.hpp"
#include "extent.hpp"
#include "constants.hpp"
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
// Whether a collider may belong to a resting group (see RestingGroups): it
// reports no contacts (its report names other bodies), follows no group,
// and neither carries nor is crushed (the carriers' steps read riders by
// their own rules, which the reach test below does not cover).
inline bool may_rest(const Body& b) {
    return b.collides() && !b.contacts && b.group == 0 && !b.carries && !b.crushed;
}
// Whether any body collides (Body::collides): then ground detection has
// supporters to look for.
DOWNSTROKE_API bool any_collider(std::span<const Body> bodies);
// No speed, and depending on nobody: a body that can settle.
inline bool can_settle(const Body& b, bool colliders) {
    return b.vx.v == 0 && b.vy.v == 0 && !depends_on_others(b, colliders);
}
// No speed, and either depending on nobody or a collider that may rest in
// a group: a body that may come to sleep (what tracking is for).
inline bool can_sleep(const Body& b, bool colliders) {
    return b.vx.v == 0 && b.vy.v == 0 && (!depends_on_others(b, colliders) || may_rest(b));
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

// Resting groups of colliders (both paths' sleeping for bodies that
// push each other). A frame's resting group is a set of colliders that
// may_rest, that the frame left exactly as they entered, and whose rooms
// (Extent: every box a member took in the frame, its pass included) reach
// no collider's outside the set: the components, under Extent::reaches,
// of every collider, kept when every body of one is such a body. A group is
// asleep in the next frame when every member enters as left with no tween,
// under the same conditions, in a frame with no carriers, crushed bodies,
// group followers, contact reports or sensors (whose steps read bodies by
// rules the rooms do not bound). Asleep members stay supporters for the
// awake bodies; the push-apart pass and the put-out leave them out. Before
// each push-apart the frame tests every awake collider's room so far
// against the asleep members' rooms (each one's room over the last frame it
// was stepped, which its skipped frame would repeat): one that reaches a
// member wakes its group. In the first sub-frame the woken group is
// stepped on the spot (a per-entity step reads only its own body and the
// frame-start supporters, so that is stepping it with the rest) and tested
// in turn; in a later one the frame runs again from its start with the
// group awake. After each push-apart the test is made again, the rooms
// now holding every box the pass gave a body, and a group reached then
// makes the frame run again from its start with it awake.
//
// Why that is exact. In a frame without those roles, a collider's frame
// reads: its own fields, the map and the options; the (sub-)frame-start
// supporters its ground detection and resting check find (overlapping it
// along x, within kOnSolidTolerance of its feet); in push-apart, the
// colliders its box overlaps as the pass goes, each as earlier pairs left
// it; and the put-out reads only itself and the map. Each of those reads
// is between two boxes the two rooms hold, so the rooms reach. When group
// G formed, no collider outside G reached it, so G's frame read only G's
// own bodies, the map and the options, and it left G as it was. In the
// next frame G's members enter as left, the map and the options are the
// same, and — tested before and after each push-apart, with the frame run
// again otherwise — nothing outside G reaches the room G's frame would
// take (the same as the last time, so long as it reads the same): G's
// frame would read the same and so leave G as it was again, which is what
// not stepping it does. The awake bodies read of G only its members as
// supporters (frame-start values, which asleep members keep) and never
// meet it in push-apart, so they step as they would beside a stepped G.
// Non-colliders neither push nor hold up.
class DOWNSTROKE_API RestingGroups {
public:
    // A frame of n bodies: the last frame's groups may sleep (`keep`), or
    // none is a group any more.
    void begin(size_t n, bool keep);
    // Planning: member i enters as left with no tween (`fit`), or its group
    // stays awake.
    void propose(size_t i, bool fit) {
        const int32_t g = group_[i];
        if (g >= 0 && !fit) asleep_[static_cast<size_t>(g)] = 0;
    }
    // Whether this frame may let groups sleep at all (see above); call
    // after every propose().
    void allow(bool allowed);
    bool asleep(size_t i) const {
        const int32_t g = group_[i];
        return g >= 0 && asleep_[static_cast<size_t>(g)];
    }
    bool any_asleep() const { return any_asleep_; }
    // Whether body i is in a group (formed by the last form()).
    bool grouped(size_t i) const { return i < group_.size() && group_[i] >= 0; }
    bool any_group() const { return groups_ != 0; }

    // Stepping: an awake collider's extent starts at its frame-start box
    // and grows with each box it takes before a push-apart.
    void start(size_t i, const Body& b) { extent_[i] = Extent::of(b); }
    void extend(size_t i, const Body& b) { extent_[i].add(b); }
    // The extents by body, for push-apart to extend (ContactScratch::rooms).
    Extent* extents() { return extent_.data(); }
    // Files the asleep members' rooms for reached() (once a frame run).
    void file_asleep(std::span<const size_t> members);
    // Marks to wake each asleep group collider i's extent reaches; returns
    // whether it reached any not marked yet.
    bool reached(size_t i);
    // Whether member i's group is marked to wake.
    bool marked(size_t i) const {
        const int32_t g = group_[i];
        return g >= 0 && wake_[static_cast<size_t>(g)];
    }
    // Wakes the marked groups. Returns whether any.
    bool wake_marked();

    // After the frame: forms the next frame's groups from every collider
    // (`members`, list order) and, by body, whether the frame left it as
    // it entered with no tween (`unchanged`, for the bodies stepped).
    void form(std::span<const Body> bodies, std::span<const size_t> members, std::span<const uint8_t> unchanged);
    void forget();  // no group

private:
    size_t find(size_t m);
    // Groups are looked for only when at least 1 in kFitShare colliders may
    // rest (see form()).
    static constexpr size_t kFitShare = 2;
    struct Filed {
        Extent box;
        int32_t group;
    };
    std::vector<int32_t> group_;   // by body: its resting group, -1 for none
    std::vector<uint8_t> asleep_;  // by group, this frame
    std::vector<uint8_t> wake_;    // by group: reached this frame run
    bool any_asleep_ = false, any_wake_ = false;
    std::vector<Extent> extent_;   // by body (awake colliders), this frame so far
    // By body (members of groups): the room it took the last frame it was
    // stepped. An asleep member's skipped frame would take the same room, so
    // that, not its box, is what an awake collider must not reach.
    std::vector<Extent> room_;
    std::vector<Filed> filed_;     // asleep members' rooms, by x0
    double widest_ = 0;            // the widest room in filed_
    // form()'s scratch: by member (position in `members`), its extent, its
    // union–find parent, and whether it may rest; members by x0.
    std::vector<Extent> ext_;
    std::vector<uint32_t> parent_, order_;
    std::vector<uint8_t> fit_, root_fit_;
    std::vector<int32_t> root_group_;
    size_t groups_ = 0;
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
        groups_.propose(i, as_left_[i] && !has_tween_[i]);
    }
    // After every propose(): whether resting groups may sleep this frame.
    void allow_groups(bool allowed) { groups_.allow(allowed); }
    bool confirm(size_t i, bool colliders) { return marks_.confirm(i, colliders) | groups_.asleep(i); }
    void settle(size_t i, const Body& b, bool colliders);
    // After every settle(): the next frame's resting groups.
    void form_groups(std::span<const Body> bodies, std::span<const size_t> members) {
        groups_.form(bodies, members, unchanged_);
    }
    RestingGroups& groups() { return groups_; }
    // Whether body i sleeps this frame as a settled body of its own.
    std::span<const uint8_t> asleep_alone() const { return marks_.asleep(); }

    // Not tracking: forgets every copy (nothing is settled), and counts.
    void skip();
    bool counting() const { return counting_; }
    void count(const Body& b, bool colliders) { counted_ += can_sleep(b, colliders); }

    // Every frame, at its end: whether the next one tracks.
    void end_frame(size_t n);

private:
    Settling marks_;
    RestingGroups groups_;
    std::vector<Body> left_;  // by body: as the last frame left it
    // By body, this frame: entered as left, has a tween, and (for the
    // bodies stepped) left as entered with no tween.
    std::vector<uint8_t> as_left_, has_tween_, unchanged_;
    std::vector<uint8_t> can_settle_;           // by body, after the last frame
    size_t can_settle_count_ = 0;
    size_t counted_ = 0;  // this frame, when not tracking
    bool same_ = false;  // this frame: the last one's bodies and conditions
    bool tracking_ = true, counting_ = false;
};

}  // namespace ds
