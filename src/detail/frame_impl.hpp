// SPDX-License-Identifier: MIT
// What a Frame keeps between frames and the passes that use it: the
// frame-start scene, the supporters and their index, the census of roles,
// push-apart's and the groups' scratch, settling. Private to the core.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "../carry.hpp"
#include "../frame.hpp"
#include "../settle.hpp"
#include "contact_scratch.hpp"
#include "first_writes.hpp"
#include "group_scratch.hpp"
#include "stopwatch.hpp"
#include "support_index.hpp"
#include "supporter.hpp"

namespace ds {

struct Frame::Impl {
    const FrameReport& step(World& world, const FrameOptions& opts);
    void step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                      std::span<const Body> scene, std::span<FirstWrites> writes,
                      std::span<const uint8_t> asleep);
    void step_physics_resting(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                              std::span<const Body> scene, std::span<FirstWrites> writes,
                              std::span<const uint8_t> asleep, std::span<const uint8_t> fit, bool keep);
    void step_tweens(World& world, double dt);
    void plan_sleep(const World& world, const FrameOptions& opts);
    void note_settled(const World& world);
    // The per-entity steps over `active` (list order); `more`: over bodies
    // woken after the call that stepped the others in this sub-frame.
    void step_bodies(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                     int round, std::span<FirstWrites> writes, std::span<const uint32_t> active, bool more);
    // The census finds each body's roles; with `take`, in the same sweep it
    // copies out the supporters, which the bodies then must be the
    // frame-start scene for (a large scene is read once instead of twice).
    void census(std::span<const Body> bodies, std::span<const uint8_t> asleep, bool take);
    void begin_census(size_t n, bool take);
    void enlist(const Body& b, size_t i);  // the census's count of one body's roles
    void end_census();
    void clear_supporters(size_t n);
    void add_supporter(const Body& b, size_t i);
    // Returns whether it stopped short because an awake collider reached an
    // asleep resting group (marked to wake: the frame must run again).
    bool run_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                     std::span<const Body> scene, std::span<FirstWrites> writes);
    // Resting groups (settle.hpp): the awake colliders' extents so far
    // against the asleep members, before a push-apart and after it; the
    // awake members; and the frame put back to its start with the reached
    // groups awake (after a later sub-frame, or a pass, reached them).
    bool reaches_asleep(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                        std::span<FirstWrites> writes, int round);
    bool took_room_after_pass(std::span<const Body> bodies, std::span<const size_t> pass);
    void merge_into(std::vector<uint32_t>& list, std::span<const uint32_t> more);
    void save_for_rerun(std::span<const Body> bodies, std::span<const FirstWrites> writes,
                        std::span<const uint32_t> which);
    // After the census and each member's proposal: whether groups may sleep
    // this frame, and the awake bodies (`alone`: asleep as settled bodies).
    void plan_groups(std::span<const Body> bodies, std::span<const uint8_t> alone);
    void note_awake_members();
    // The frame's physics, run again from its start while a later sub-frame
    // reaches an asleep group.
    void run_waking(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                    std::span<const Body> scene, std::span<FirstWrites> writes, std::span<const uint8_t> alone);
    void wake_reached(std::span<Body> bodies, std::span<FirstWrites> writes, std::span<const uint8_t> alone);
    void take_supporters(std::span<const Body> scene);
    bool rests(const Body& b, size_t i, const TileGrid* grid, bool indexed);
    // The carriers' steps around push-apart (semantics §11), in frames that
    // have a carrier or a crushed body.
    void start_carry(std::span<const Body> start);
    void carry(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
               std::span<FirstWrites> writes);
    // The default push rule's last word (§4): members left inside solid cells
    // are put out of them.
    void put_members_out(std::span<Body> bodies, const TileGrid& grid, std::span<const size_t> members);
    void crush(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
               std::span<FirstWrites> writes);
    // A contact body's #:standing-on after detect-on-solid ran (semantics §10).
    void note_standing(Body& b, size_t i, bool indexed);
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
    // The sensors (Body::senses), and with them the bodies of the push-apart
    // pass: members_ and the sensors merged in list order (§13). Empty, and
    // the pass takes members_, in a frame without sensors.
    std::vector<size_t> sensors_;
    std::vector<size_t> pair_members_;
    std::span<const size_t> pass_members() const {
        return sensors_.empty() ? std::span<const size_t>(members_) : std::span<const size_t>(pair_members_);
    }
    uint64_t grouped_ = 0;
    // Bodies with a drag or a speed cap (semantics §14): without any, the
    // frame does not walk the bodies for apply_speed_limits at all.
    uint64_t limited_ = 0;
    std::vector<size_t> carriers_;        // the members that are carriers, in list order
    bool crushed_ = false;                // some crushable member enters the frame crushed
    std::vector<Body> carry_start_;       // the bodies at the (sub-)frame start, for the carry
    CarryScratch carry_scratch_;
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
    // This frame: whether resting groups may sleep (no role whose reads
    // the extents do not bound), and whether some do; then the members
    // that are awake, and the stepped bodies as the run started (for
    // running the frame again) with the list they were stepped in.
    bool groups_allowed_ = false, groups_asleep_ = false;
    // Whether groups form at this frame's end: every awake collider's
    // extent then takes its box before each push-apart (settle.hpp).
    bool groups_forming_ = false;
    std::vector<size_t> awake_members_;
    std::vector<uint32_t> rerun_index_;  // with sub-frames (only a later one runs the frame again)
    std::vector<Body> rerun_from_;
    std::vector<FirstWrites> rerun_writes_;  // beside rerun_from_, for a caller that logs first writes
    std::vector<uint32_t> woken_, merged_;  // members woken in the first sub-frame
    bool index_built_ = false;              // support_index_, this sub-frame
    // The contact report (semantics §10): this frame's bodies with
    // #:contacts? or sensors (whose pairs the scene keeps, §13), and where push-apart logs its pairs meanwhile (the
    // overlay's log when it has one, else the frame's own) from which offset.
    size_t contact_bodies_ = 0;
    PairLog* overlay_log_ = nullptr;
    PairLog frame_pairs_;
    size_t pairs_from_ = 0;
    SideLog frame_sides_;  // beside the log from pairs_from_: each pair's first body's side
    void begin_contact_log();
    void end_contact_log() { contacts_.log = overlay_log_; }
};

}  // namespace ds
