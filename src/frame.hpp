// One whole engine pass, the composition of default-engine-update (semantics §5):
// tweens; per-entity motion and tile steps against the frame-start scene;
// then entity push-apart; then groups.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "body.hpp"
#include "contacts.hpp"
#include "frame_options.hpp"
#include "groups.hpp"
#include "settle.hpp"
#include "stopwatch.hpp"
#include "tile_grid.hpp"
#include "support_index.hpp"
#include "supporter.hpp"
#include "tiles.hpp"
#include "tween.hpp"

namespace ds {

// Property ids a tween can drive directly on a body. Ids from kFirstUserKey up
// name properties physics does not know; their values are handed back.
// Every Number field of body_fields.def has one, numbered as its Field bit.
enum Key : uint32_t {
#define DS_KEY_ID_Number(Name) kKey##Name = kFieldBit##Name,
#define DS_KEY_ID_Flag(Name)
#define DS_FIELD(Name, type, member, keyword, rule) DS_KEY_ID_##rule(Name)
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
#undef DS_KEY_ID_Number
#undef DS_KEY_ID_Flag
    kFirstUserKey = 16,
};
static_assert(kFieldCount <= kFirstUserKey);

// The body field a physics key names, or nullptr for a user key.
Num* body_field(Body& b, uint32_t key);

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
    kStepTweens, kStepAcceleration, kStepGravity, kStepVelocityX, kStepTileX, kStepVelocityY,
    kStepTileY, kStepOnSolid, kStepEntityCollisions, kStepGroups, kStepCount,
};
const char* step_name(StepId id);  // the skip symbol's spelling: "velocity-x", "groups", …

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
class Frame {
public:
    // The whole pass over a world.
    const FrameReport& step(World& world, const FrameOptions& opts);

    // The cost of each step in the last frame (tweens: only when step() ran
    // them; callers running tweens themselves may record theirs here).
    const FrameStats& stats() const { return stats_; }

    // Where push-apart notes the pairs it resolves (the debug overlay), or
    // nullptr for nowhere, from the next frame on.
    void note_pairs(PairLog* log) { contacts_.log = log; }
    FrameStats& stats() { return stats_; }

    // Everything after step-tweens, for callers that run tweens themselves.
    // `scene` is the frame-start state ground detection reads (before the
    // tweens); empty means the bodies as they are now. With `writes` (one per
    // body), each step's first writes to watched fields are logged in order.
    // Bodies marked in `asleep` (Settling::asleep) are left as they are: the
    // caller knows the frame cannot change them (settle.hpp).
    void step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                      std::span<const Body> scene = {}, std::span<FirstWrites> writes = {},
                      std::span<const uint8_t> asleep = {});

private:
    void step_tweens(World& world, double dt);
    void plan_sleep(const World& world, const FrameOptions& opts);
    void note_settled(const World& world);
    void step_bodies(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                     int round, std::span<FirstWrites> writes);
    // The census finds each body's roles; with `take`, in the same sweep it
    // copies out the supporters, which the bodies then must be the
    // frame-start scene for (a large scene is read once instead of twice).
    void census(std::span<const Body> bodies, std::span<const uint8_t> asleep, bool take);
    void begin_census(size_t n, bool take);
    void enlist(const Body& b, size_t i);  // the census's count of one body's roles
    void end_census();
    void clear_supporters(size_t n);
    void add_supporter(const Body& b, size_t i);
    void run_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                     std::span<const Body> scene, std::span<FirstWrites> writes);
    void take_supporters(std::span<const Body> scene);
    bool rests(const Body& b, size_t i, const TileGrid* grid, bool indexed);
    // One step over a block of active_; adds to the step's processed count
    // and, from t0 to its return value (now), to its time.
    template <class MayWrite, class Step>
    Clock::time_point pass(StepId id, std::span<const uint32_t> block, std::span<Body> bodies,
                           std::span<FirstWrites> writes, Clock::time_point t0, MayWrite&& may_write,
                           Step&& step);
    template <class Bulk>
    void logged_bulk(std::span<Body> bodies, std::span<FirstWrites> writes, uint32_t may_write,
                     Bulk&& bulk);


    std::vector<Body> start_;  // the frame-start scene (before tweens)
    // The frame-start bodies that can hold another up (solid, not ghosts),
    // and each body's slot among them (-1 when it is not one): ground
    // detection scans only these.
    std::vector<Supporter> supporters_;
    std::vector<std::ptrdiff_t> support_slot_;
    // This call's bodies by role, found in one sweep (a frame changes no
    // flag): those the per-entity steps visit (awake), those that
    // collide, in list order, and how many follow a group.
    std::vector<uint32_t> active_;
    std::vector<size_t> members_;
    std::vector<size_t> slotted_;  // the bodies support_slot_ gave a slot to
    uint64_t grouped_ = 0;
    bool supporters_taken_ = false;  // by the census, for the first sub-frame
    std::vector<uint8_t> resting_;   // by body, this sub-frame: rested (resting contacts)
    std::vector<Body> bulk_before_;  // for logging what a bulk step wrote
    SupportIndex support_index_;     // over supporters_, when there are many
    ContactScratch contacts_;        // push-apart's grid (and the overlay's pair log)
    GroupScratch groups_;            // sync_groups's origins
    FrameReport report_;
    FrameStats stats_;
    SettleTracker settling_;  // which bodies step() may leave asleep (World path)
    bool colliders_ = false;  // this frame: any body that collides (flags do not change in a frame)
};

}  // namespace ds
