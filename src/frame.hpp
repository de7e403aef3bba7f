// SPDX-License-Identifier: MIT
// One whole engine pass, the composition of default-engine-update (semantics §5):
// tweens; per-entity motion and tile steps against the frame-start scene;
// then entity push-apart; then groups.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "body.hpp"
#include "contacts.hpp"
#include "frame_options.hpp"
#include "tile_grid.hpp"
#include "tween.hpp"
#include "export.hpp"

namespace ds {

// The bindings' log of first writes (detail/first_writes.hpp): a C++
// program passes none.
struct FirstWrites;

// Property ids a tween can drive directly on a body. Ids from kFirstUserKey up
// name properties physics does not know; their values are handed back.
// Every Number field of body_fields.def has one, numbered as its Field bit.
enum Key : uint32_t {
#define DS_KEY_ID_Number(Name) kKey##Name = kFieldBit##Name,
#define DS_KEY_ID_Flag(Name)
#define DS_KEY_ID_Sides(Name)
#define DS_KEY_ID_Report(Name)
#define DS_FIELD(Name, type, member, keyword, rule) DS_KEY_ID_##rule(Name)
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
#undef DS_KEY_ID_Number
#undef DS_KEY_ID_Flag
#undef DS_KEY_ID_Sides
#undef DS_KEY_ID_Report
    kFirstUserKey = 16,
};
static_assert(kFieldCount <= kFirstUserKey);

// The body field a physics key names, or nullptr for a user key.
DOWNSTROKE_API Num* body_field(Body& b, uint32_t key);

struct TweenTrack {
    uint32_t body = 0;  // index into World::bodies
    std::vector<TweenProp> props;
    TweenTiming timing;
    Ease ease = Ease::Linear;
    double elapsed = 0;
};

struct UserWrite {  // a tween's value for a key physics does not hold
    uint32_t body;
    uint32_t key;
    Num value;
};

struct World {
    std::vector<Body> bodies;
    std::vector<TweenTrack> tweens;  // at most one per body
    const TileGrid* grid = nullptr;  // none: tile steps do nothing
};

// The steps of a frame, in order, for reporting what each cost.
enum StepId : int {
    kStepTweens, kStepAcceleration, kStepGravity, kStepSpeedLimits, kStepVelocityX, kStepTileX, kStepVelocityY,
    kStepTileY, kStepOnSolid, kStepEntityCollisions, kStepGroups, kStepCount,
};
DOWNSTROKE_API const char* step_name(StepId id);  // the skip symbol's spelling: "velocity-x", "groups", …

// For one step of the last frame: bodies it applied to, bodies it left
// alone (guarded out, skipped by #:skip-pipelines, nothing to do such as no
// speed on a tile step's axis, not solid, not in a group, asleep), and wall
// time.
struct StepStats {
    uint64_t processed = 0;
    uint64_t skipped = 0;
    double ms = 0;
};
struct FrameStats {
    StepStats step[kStepCount];
};

// What a frame did besides moving bodies.
struct FrameReport {
    std::vector<UserWrite> user_writes;
    std::vector<uint32_t> completed;  // bodies whose tween finished this frame
};

// Runs frames; keeps its scratch memory between them, so a warm Frame does
// not allocate.
class DOWNSTROKE_API Frame {
public:
    Frame();
    ~Frame();
    Frame(Frame&&) noexcept;
    Frame& operator=(Frame&&) noexcept;

    // The whole pass over a world: default-engine-update (semantics §5).
    const FrameReport& step(World& world, const FrameOptions& opts);

    // The cost of each step in the last frame (tweens: only when step() ran
    // them; callers running tweens themselves may record theirs here).
    const FrameStats& stats() const;

    // Where push-apart notes the pairs it resolves (the debug overlay), or
    // nullptr for nowhere, from the next frame on.
    void note_pairs(PairLog* log);
    FrameStats& stats();

    // The pairs push-apart resolved in the last frame, in the order
    // resolved (sub-frames one after the other), when it had bodies with
    // #:contacts? (semantics §10); empty otherwise. Valid until the next frame.
    std::span<const std::pair<uint32_t, uint32_t>> contact_pairs() const;
    // Beside contact_pairs, pair for pair: the side of the first body that
    // met the second (a kSide bit), as push-apart decided it (§10).
    std::span<const uint8_t> contact_sides() const;

    // Everything after step-tweens, for callers that run tweens themselves.
    // `scene` is the frame-start state ground detection reads (before the
    // tweens); empty means the bodies as they are now. `writes` serves the
    // bindings (one per body: each step's first writes to watched fields,
    // logged in order); a C++ program leaves it empty.
    // Bodies marked in `asleep` (Settling::asleep) are left as they are: the
    // caller knows the frame cannot change them (settle.hpp).
    void step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                      std::span<const Body> scene = {}, std::span<FirstWrites> writes = {},
                      std::span<const uint8_t> asleep = {});
    // step_physics with resting groups of colliders asleep too, as step()
    // lets them sleep (settle.hpp's RestingGroups), for a caller that knows
    // bodies only by position: `fit`, by body, whether it enters the frame
    // as the last frame left it, with no tween; `keep`, whether the groups
    // the last frame formed still stand (the same conditions and bodies,
    // and that frame completed). A group an awake collider reaches is woken
    // and the frame, first writes included, comes out as if every body had
    // been stepped. After the frame: resting_asleep(i), whether it left
    // body i asleep in a group, and form_resting_groups, given by body
    // whether the frame left each stepped body as it entered with no tween,
    // forms the groups the next frame may keep; then resting_grouped(i),
    // whether body i is in one of them.
    void step_physics_resting(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                              std::span<const Body> scene, std::span<FirstWrites> writes,
                              std::span<const uint8_t> asleep, std::span<const uint8_t> fit, bool keep);
    bool resting_asleep(size_t i) const;
    bool resting_grouped(size_t i) const;
    void form_resting_groups(std::span<const Body> bodies, std::span<const uint8_t> unchanged);

private:
    // The scratch and the passes (detail/frame_impl.hpp): the core's own
    // machinery, so this header needs none of its headers.
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ds
