// SPDX-License-Identifier: MIT
#include "frame.hpp"

#include <algorithm>
#include <iterator>

#include "constants.hpp"
#include "detail/frame_impl.hpp"
#include "detail/ground_index.hpp"
#include "detail/tile_clip.hpp"
#include "steps.hpp"
#include "tiles.hpp"

namespace ds {

namespace {
Num* if_num(Num& n) { return &n; }
template <class T>
Num* if_num(T&) { return nullptr; }
}  // namespace

Num* body_field(Body& b, uint32_t key) {
    switch (key) {
#define DS_FIELD(Name, type, member, keyword, rule) \
    case kFieldBit##Name: return if_num(b.member);
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
        default: return nullptr;
    }
}

void Frame::Impl::step_tweens(World& world, double dt) {
    const auto t0 = Clock::now();
    const size_t tracks = world.tweens.size();
    auto done = [&](TweenTrack& track) {
        Body& b = world.bodies[track.body];
        if (b.skips(kSkipTweens)) return false;
        track.elapsed += dt;
        const TweenPhase phase = tween_phase(track.timing, track.elapsed);
        if (!phase.started) return false;
        const double eased = ease(track.ease, phase.t);
        for (const TweenProp& p : track.props) {
            const Num v = tween_value(p, phase, eased);
            if (Num* field = body_field(b, p.key)) *field = v;
            else report_.user_writes.push_back({track.body, p.key, v});
        }
        if (phase.finished) report_.completed.push_back(track.body);
        return phase.finished;
    };
    std::erase_if(world.tweens, done);
    stats_.step[kStepTweens] = {tracks, world.bodies.size() - tracks, ms_since(t0)};
}

namespace {

// Runs one per-entity step; when it may write a field the entity lacks,
// compares around it so the first write is logged. Returns whether it applied.
template <class Step>
bool logged(Body& b, FirstWrites* w, uint32_t may_write, Step&& step) {
    if (w == nullptr || (w->watched & may_write) == 0) return step(b);
    const Body before = b;
    const bool ran = step(b);
    w->note(changed_fields(before, b) & may_write);
    return ran;
}

uint32_t unless_zero(Num n, uint32_t fields) { return n.v != 0 ? fields : 0u; }
uint32_t reported(const Body& b, uint32_t fields) { return b.contacts ? fields : 0u; }

}  // namespace

const char* step_name(StepId id) {
    static constexpr const char* kNames[kStepCount] = {
        "tweens", "acceleration", "gravity", "speed-limits", "velocity-x", "tile-collisions-x", "velocity-y",
        "tile-collisions-y", "on-solid", "entity-collisions", "groups"};
    return kNames[id];
}

template <class MayWrite, class Step>
Clock::time_point Frame::Impl::pass(StepId id, std::span<const uint32_t> block, std::span<Body> bodies,
                              std::span<FirstWrites> writes, Clock::time_point t0,
                              MayWrite&& may_write, Step&& step) {
    uint64_t ran = 0;
    for (const uint32_t i : block) {
        Body& b = bodies[i];
        ran += logged(b, writes.empty() ? nullptr : &writes[i], may_write(b),
                      [&](Body& c) { return step(c, i); });
    }
    const auto t1 = Clock::now();
    StepStats& st = stats_.step[id];
    st.processed += ran;
    st.ms += ms_between(t0, t1);
    return t1;
}

bool Frame::Impl::rests(const Body& b, size_t i, const TileGrid* grid, bool indexed) {
    if (b.vy.v != 0) return false;
    if (grid && rests_on_tile(b, *grid)) return true;
    auto on = [&](size_t k) {
        return !is_self(b, supporters_[k], static_cast<std::ptrdiff_t>(k), support_slot_[i]) &&
               rests_on(b, supporters_[k]);
    };
    if (indexed) return support_index_.any(b, on);
    for (size_t k = 0; k < supporters_.size(); ++k)
        if (on(k)) return true;
    return false;
}

void Frame::Impl::note_standing(Body& b, size_t i, bool indexed) {
    const std::ptrdiff_t slot = indexed ? first_supporter(b, supporters_, support_index_, support_slot_[i])
                                        : first_supporter(b, supporters_, support_slot_[i]);
    // Supporters are the colliding bodies in list order: slot k is members_[k].
    b.standing_on = slot < 0 ? 0 : static_cast<int32_t>(members_[static_cast<size_t>(slot)] + 1);
}

void Frame::Impl::begin_contact_log() {
    // The sides follow the overlay's log too, which others clear.
    frame_sides_.clear();
    contacts_.sides = &frame_sides_;
    if (contact_bodies_ == 0) return;
    if (overlay_log_ == nullptr) {
        frame_pairs_.clear();
        contacts_.log = &frame_pairs_;
    }
    pairs_from_ = contacts_.log->size();
}

void Frame::Impl::step_bodies(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                        int round, std::span<FirstWrites> writes, std::span<const uint32_t> active, bool more) {
    // Step by step over a block of bodies, block after block: the same
    // result as step by step over all of them (each per-entity step reads
    // only its own body and the frame-start supporters), each step's cost
    // can still be reported, and a block stays in cache through all eight
    // steps, where whole-list passes would stream a large scene from memory
    // eight times. The masks say what a step can write given the body as it
    // is: acceleration resets only a non-zero ay, tile steps do nothing at
    // zero speed.
    const CollisionMode mode = opts.mode;
    SubStep sub = SubStep::of_frame(opts.substeps);
    sub.gather = round > 0;
    const auto t0 = Clock::now();
    // (With every body asleep nobody looks for a supporter: the index is
    // built when the first body is stepped.)
    const bool indexed = supporters_.size() >= kSupportIndexFrom;
    if (!more) index_built_ = false;
    if (indexed && !index_built_ && !active.empty()) {
        support_index_.build(supporters_);
        index_built_ = true;
    }
    stats_.step[kStepOnSolid].ms += ms_since(t0);
    if (!more) resting_.assign(opts.resting_contacts ? bodies.size() : 0, 0);
    uint64_t before[kStepCount];
    for (int id = 0; id < kStepCount; ++id) before[id] = stats_.step[id].processed;
    for (size_t lo = 0; lo < active.size(); lo += kStepBlock) {
        const auto block = active.subspan(lo, std::min(kStepBlock, active.size() - lo));
        auto t = Clock::now();
        if (round == 0)
            t = pass(kStepAcceleration, block, bodies, writes, t,
                     [](const Body& b) { return kFieldVy | unless_zero(b.ay, kFieldAy); },
                     [](Body& b, size_t) { return apply_acceleration(b); });
        t = pass(kStepGravity, block, bodies, writes, t, [](const Body&) { return kFieldVy; },
                 [&](Body& b, size_t i) {
                     if (opts.resting_contacts && b.gravity && !b.skips(kSkipGravity) &&
                         pulled_down(b, opts.gravity) && rests(b, i, grid, indexed)) {
                         resting_[i] = 1;
                         return false;
                     }
                     return apply_gravity(b, sub, opts.gravity);
                 });
        if (limited_ != 0)
            t = pass(kStepSpeedLimits, block, bodies, writes, t,
                     [](const Body& b) { return b.limits_speed() ? kFieldVx | kFieldVy : 0u; },
                     [&](Body& b, size_t) { return apply_speed_limits(b, sub); });
        t = pass(kStepVelocityX, block, bodies, writes, t, [](const Body&) { return kFieldX; },
                 [&](Body& b, size_t) { return apply_velocity_x(b, sub); });
        t = pass(kStepTileX, block, bodies, writes, t,
                 // A grid with shapes lifts bodies up ramps from this step (§12).
                 [&](const Body& b) {
                     const uint32_t y = grid && grid->has_shapes() ? kFieldY : 0u;
                     return unless_zero(b.vx, kFieldX | kFieldVx | y) | reported(b, kFieldBlocked);
                 },
                 [&](Body& b, size_t) { return resolve_tile_collisions_x(b, grid, mode, sub); });
        t = pass(kStepVelocityY, block, bodies, writes, t, [](const Body&) { return kFieldY; },
                 [&](Body& b, size_t) { return apply_velocity_y(b, sub); });
        t = pass(kStepTileY, block, bodies, writes, t,
                 [](const Body& b) { return unless_zero(b.vy, kFieldY | kFieldVy) | reported(b, kFieldBlocked); },
                 [&](Body& b, size_t) { return resolve_tile_collisions_y(b, grid, mode, sub); });
        pass(kStepOnSolid, block, bodies, writes, t,
             [](const Body& b) { return kFieldOnGround | reported(b, kFieldStandingOn); },
             [&](Body& b, size_t i) {
                 const bool ran = indexed ? detect_on_supporters(b, supporters_, support_index_, support_slot_[i], grid)
                                          : detect_on_supporters(b, supporters_, support_slot_[i], grid);
                 if (ran && b.contacts) note_standing(b, i, indexed);
                 return ran;
             });
        // The bodies that can settle, counted while the block is in cache
        // (when step() does not track settling). Nothing later in the frame
        // moves a body that depends on nobody, and one that does never counts.
        if (settling_.counting() && round + 1 == std::max(1, opts.substeps))
            for (const uint32_t i : block) settling_.count(bodies[i], colliders_);
    }
    // A step leaves alone every body it did not apply to, asleep ones
    // included (and `more` steps bodies the first call counted as left alone).
    for (int id = kStepAcceleration; id <= kStepOnSolid; ++id) {
        if (id == kStepAcceleration && round != 0) continue;
        const uint64_t applied = stats_.step[id].processed - before[id];
        stats_.step[id].skipped += more ? 0 - applied : bodies.size() - applied;
    }
}

template <class Bulk>
void Frame::Impl::logged_bulk(std::span<Body> bodies, std::span<FirstWrites> writes, uint32_t may_write,
                        Bulk&& bulk) {
    const bool log = std::any_of(writes.begin(), writes.end(),
                                 [&](const FirstWrites& w) { return (w.watched & may_write) != 0; });
    if (log) bulk_before_.assign(bodies.begin(), bodies.end());
    bulk(bodies);
    if (!log) return;
    for (size_t i = 0; i < bodies.size(); ++i)
        if (writes[i].watched & may_write)
            writes[i].note(changed_fields(bulk_before_[i], bodies[i]) & may_write);
}

void Frame::Impl::census(std::span<const Body> bodies, std::span<const uint8_t> asleep, bool take) {
    active_.clear();
    begin_census(bodies.size(), take);
    for (size_t i = 0; i < bodies.size(); ++i) {
        if (asleep.empty() || !asleep[i]) active_.push_back(static_cast<uint32_t>(i));
        enlist(bodies[i], i);
    }
    end_census();
}

void Frame::Impl::begin_census(size_t n, bool take) {
    members_.clear();
    sensors_.clear();
    carriers_.clear();
    crushed_ = false;
    grouped_ = 0;
    limited_ = 0;
    contact_bodies_ = 0;
    supporters_taken_ = take;
    if (take) clear_supporters(n);
}

void Frame::Impl::enlist(const Body& b, size_t i) {
    if (b.collides()) {
        members_.push_back(i);
        if (supporters_taken_) add_supporter(b, i);
        if (b.carries | b.crushed) {
            if (is_carrier(b)) carriers_.push_back(i);
            crushed_ |= b.crushed;
        }
    }
    if (b.senses()) sensors_.push_back(i);
    grouped_ += b.group != 0;
    limited_ += b.limits_speed();
    contact_bodies_ += b.reports_pairs();
}

void Frame::Impl::end_census() {
    colliders_ = !members_.empty();
    pair_members_.clear();
    if (!sensors_.empty())
        std::merge(members_.begin(), members_.end(), sensors_.begin(), sensors_.end(),
                   std::back_inserter(pair_members_));
    if (supporters_taken_) slotted_.assign(members_.begin(), members_.end());
}

void Frame::Impl::clear_supporters(size_t n) {
    // Only the slots handed out last time need clearing.
    if (support_slot_.size() != n) support_slot_.assign(n, -1);
    else
        for (const size_t i : slotted_) support_slot_[i] = -1;
    supporters_.clear();
}

void Frame::Impl::add_supporter(const Body& b, size_t i) {
    support_slot_[i] = std::ssize(supporters_);
    supporters_.push_back(Supporter::of(b));
}

void Frame::Impl::take_supporters(std::span<const Body> scene) {
    clear_supporters(scene.size());
    for (const size_t i : members_) add_supporter(scene[i], i);
    slotted_.assign(members_.begin(), members_.end());
}

void Frame::Impl::step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                         std::span<const Body> scene, std::span<FirstWrites> writes,
                         std::span<const uint8_t> asleep) {
    census(bodies, asleep, false);
    groups_asleep_ = groups_forming_ = false;
    run_physics(bodies, grid, opts, scene, writes);
}

void Frame::Impl::step_physics_resting(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                                       std::span<const Body> scene, std::span<FirstWrites> writes,
                                       std::span<const uint8_t> asleep, std::span<const uint8_t> fit, bool keep) {
    const size_t n = bodies.size();
    RestingGroups& groups = settling_.groups();
    groups.begin(n, keep);
    // The bodies are after the tweens: run_physics copies out the
    // supporters, and only when some body is awake to read them.
    begin_census(n, false);
    for (size_t i = 0; i < n; ++i) {
        enlist(bodies[i], i);
        groups.propose(i, fit[i]);
    }
    end_census();
    plan_groups(bodies, asleep);
    run_waking(bodies, grid, opts, scene, writes, asleep);
}

void Frame::Impl::run_waking(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                             std::span<const Body> scene, std::span<FirstWrites> writes,
                             std::span<const uint8_t> alone) {
    // A frame with asleep groups runs again, with the groups an awake
    // collider reached woken, until none is reached (settle.hpp).
    for (;;) {
        rerun_index_.clear();
        rerun_from_.clear();
        rerun_writes_.clear();
        if (groups_asleep_) save_for_rerun(bodies, writes, active_);
        if (!run_physics(bodies, grid, opts, scene, writes)) break;
        wake_reached(bodies, writes, alone);
    }
}

bool Frame::Impl::run_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                        std::span<const Body> scene, std::span<FirstWrites> writes) {
    for (StepId id = kStepAcceleration; id < kStepCount; id = static_cast<StepId>(id + 1))
        stats_.step[id] = {};
    begin_contact_log();
    // With sub-frames, every statistic adds up over them.
    const int rounds = std::max(1, opts.substeps);
    for (int round = 0; round < rounds; ++round) {
        // Ground detection reads only the supporters, copied out before any
        // body moves: the caller's frame-start scene (before the tweens) for
        // the first sub-frame, else the bodies as this sub-frame finds them.
        // The census may have taken the frame-start supporters already.
        if (round > 0 || (!supporters_taken_ && !active_.empty()))
            take_supporters(round == 0 && !scene.empty() ? scene : std::span<const Body>(bodies));
        const bool carrying = !carriers_.empty();
        // A body crushed last frame is not crushed any more unless this frame
        // crushes it again (the key is present: no first write to log).
        if (round == 0 && crushed_) clear_crushed(bodies, members_);
        if (carrying) start_carry(round == 0 && !scene.empty() ? scene : std::span<const Body>(bodies));
        step_bodies(bodies, grid, opts, round, writes, active_, false);
        auto t0 = Clock::now();
        if (carrying) carry(bodies, grid, opts, writes);
        if (groups_asleep_) {
            if (reaches_asleep(bodies, grid, opts, writes, round)) {
                end_contact_log();
                return true;
            }
        } else if (groups_forming_) {
            RestingGroups& groups = settling_.groups();
            for (const size_t i : members_) groups.extend(i, bodies[i]);
        }
        const bool reports = contact_bodies_ != 0;
        // Asleep members meet nobody in push-apart (none reaches them) and
        // are out of every solid already: the pass and the put-out leave them out.
        const std::span<const size_t> pass = groups_asleep_ ? std::span<const size_t>(awake_members_) : pass_members();
        contacts_.walls = opts.push == PushRule::Clipped ? grid : nullptr;
        contacts_.rooms = groups_forming_ ? settling_.groups().extents() : nullptr;
        const bool put_out = contacts_.walls && !members_.empty();
        if (pass.size() >= 2 || reports || put_out)
            logged_bulk(bodies, writes, kFieldX | kFieldY | kFieldVx | kFieldVy | (reports ? kFieldTouching : 0u),
                        [&](std::span<Body> bs) {
                            if (pass.size() >= 2) resolve_entity_collisions_among(contacts_, bs, pass, resting_);
                            if (put_out)
                                put_members_out(bs, *grid, groups_asleep_ ? pass : std::span<const size_t>(members_));
                            if (reports) mark_touching(bs);
                        });
        if (groups_forming_ && took_room_after_pass(bodies, pass)) {
            end_contact_log();
            return true;
        }
        if (carrying) crush(bodies, grid, opts, writes);
        const auto solid = static_cast<uint64_t>(groups_asleep_ ? pass.size() : supporters_.size());
        StepStats& push = stats_.step[kStepEntityCollisions];
        push = {push.processed + solid, push.skipped + bodies.size() - solid, push.ms + ms_since(t0)};
        t0 = Clock::now();
        if (grouped_ != 0)
            logged_bulk(bodies, writes, kFieldX | kFieldY,
                        [&](std::span<Body> bs) { sync_groups(groups_, bs); });
        StepStats& groups = stats_.step[kStepGroups];
        groups = {groups.processed + grouped_, groups.skipped + bodies.size() - grouped_,
                  groups.ms + ms_since(t0)};
    }
    end_contact_log();
    return false;
}

bool Frame::Impl::reaches_asleep(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                                  std::span<FirstWrites> writes, int round) {
    if (awake_members_.empty()) return false;
    RestingGroups& groups = settling_.groups();
    if (round == 0) groups.file_asleep(members_);
    bool any = false;
    for (const size_t i : awake_members_) {
        groups.extend(i, bodies[i]);
        any |= groups.reached(i);
    }
    // In the first sub-frame a reached group is woken on the spot: its
    // per-entity steps read only its own bodies and the frame-start
    // supporters, so stepping it now is stepping it with the others. Its
    // new boxes may reach more groups in turn. A later sub-frame would
    // need the earlier ones again: the frame runs again instead.
    while (any && round == 0) {
        woken_.clear();
        for (const size_t i : members_)
            if (groups.asleep(i) && groups.marked(i)) woken_.push_back(static_cast<uint32_t>(i));
        groups.wake_marked();
        for (const uint32_t i : woken_) groups.start(i, bodies[i]);
        save_for_rerun(bodies, writes, woken_);
        step_bodies(bodies, grid, opts, round, writes, woken_, true);
        any = false;
        for (const uint32_t i : woken_) {
            groups.extend(i, bodies[i]);
            any |= groups.reached(i);
        }
        // Both lists stay in list order: the woken members join them.
        merge_into(active_, woken_);
        groups_asleep_ = groups.any_asleep();
        note_awake_members();
    }
    return any;
}

bool Frame::Impl::took_room_after_pass(std::span<const Body> bodies, std::span<const size_t> pass) {
    // Each awake collider's extent takes its box after the pass and the
    // put-out (where the next sub-frame, or the frame's end, finds it).
    // While groups sleep, one the pass carried within reach of an asleep
    // member means the group's frame would have met it: the frame runs again
    // from its start with that group awake.
    RestingGroups& groups = settling_.groups();
    bool any = false;
    for (const size_t i : pass) {
        groups.extend(i, bodies[i]);
        if (groups_asleep_) any |= groups.reached(i);
    }
    return any;
}

void Frame::Impl::save_for_rerun(std::span<const Body> bodies, std::span<const FirstWrites> writes,
                                 std::span<const uint32_t> which) {
    for (const uint32_t i : which) {
        rerun_index_.push_back(i);
        rerun_from_.push_back(bodies[i]);
        if (!writes.empty()) rerun_writes_.push_back(writes[i]);
    }
}

void Frame::Impl::merge_into(std::vector<uint32_t>& list, std::span<const uint32_t> more) {
    merged_.clear();
    std::merge(list.begin(), list.end(), more.begin(), more.end(), std::back_inserter(merged_));
    list.swap(merged_);
}

void Frame::Impl::put_members_out(std::span<Body> bodies, const TileGrid& grid, std::span<const size_t> members) {
    // Push-apart's pairs are cut at solid cells, but a body can begin the
    // frame in one (spawned there, or moved by its owner): it leaves by the
    // shortest way here rather than be carried on by the next tile steps.
    // Immovable bodies are placed by their owner, and a body that skips a
    // tile step has asked the map to leave it alone.
    for (const size_t i : members) {
        Body& b = bodies[i];
        if (!b.immovable && !b.skips(kSkipTileX | kSkipTileY)) put_out_of_solids(b, grid);
    }
}

void Frame::Impl::start_carry(std::span<const Body> start) {
    // The bodies move in place: the carriers' and riders' (sub-)frame-start
    // values are copied out first (the span may be the bodies themselves).
    carry_start_.assign(start.begin(), start.end());
}

void Frame::Impl::carry(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                        std::span<FirstWrites> writes) {
    logged_bulk(bodies, writes, kFieldX | kFieldY | kFieldCrushed, [&](std::span<Body> bs) {
        carry_riders(bs, carry_start_, carriers_, members_, grid, opts.mode, carry_scratch_);
        note_in_way(bs, carry_start_, carriers_, members_, carry_scratch_);
    });
}

void Frame::Impl::crush(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                        std::span<FirstWrites> writes) {
    logged_bulk(bodies, writes, kFieldCrushed, [&](std::span<Body> bs) {
        crush_in_way(bs, carriers_, grid, opts.push == PushRule::Clipped, carry_scratch_);
    });
}

void Frame::Impl::plan_sleep(const World& world, const FrameOptions& opts) {
    const size_t n = world.bodies.size();
    settling_.begin(n, SettleConditions::of(world.grid, opts));
    for (const TweenTrack& t : world.tweens) settling_.mark_tween(t.body);
    // One sweep over the bodies does the census and proposes each body's
    // sleep; whether any body collides, known after it, settles the plan.
    // While groups sleep the supporters are copied out only if a body is
    // awake to read them (run_physics), not in the census.
    begin_census(n, !settling_.groups().any_group());
    for (size_t i = 0; i < n; ++i) {
        enlist(world.bodies[i], i);
        settling_.propose(i, world.bodies[i]);
    }
    end_census();
    for (size_t i = 0; i < n; ++i) settling_.confirm(i, colliders_);
    plan_groups(world.bodies, settling_.asleep_alone());
}

void Frame::Impl::plan_groups(std::span<const Body> bodies, std::span<const uint8_t> alone) {
    // Resting groups sleep only in frames whose every read of another body
    // the extents bound (settle.hpp's RestingGroups).
    groups_allowed_ = carriers_.empty() && !crushed_ && grouped_ == 0 && contact_bodies_ == 0 &&
                      overlay_log_ == nullptr;
    groups_forming_ = groups_allowed_;
    RestingGroups& groups = settling_.groups();
    groups.allow(groups_allowed_);
    active_.clear();
    for (size_t i = 0; i < bodies.size(); ++i)
        if (!groups.asleep(i) && (alone.empty() || !alone[i])) {
            active_.push_back(static_cast<uint32_t>(i));
            if (bodies[i].collides()) groups.start(i, bodies[i]);
        }
    groups_asleep_ = groups.any_asleep();
    if (groups_asleep_) note_awake_members();
}

void Frame::Impl::note_awake_members() {
    const RestingGroups& groups = settling_.groups();
    awake_members_.clear();
    for (const size_t i : members_)
        if (!groups.asleep(i)) awake_members_.push_back(i);
}

void Frame::Impl::wake_reached(std::span<Body> bodies, std::span<FirstWrites> writes,
                               std::span<const uint8_t> alone) {
    // Back to the frame's start (after the tweens) for every body stepped,
    // first writes included, and the reached groups awake.
    for (size_t k = 0; k < rerun_index_.size(); ++k) {
        bodies[rerun_index_[k]] = rerun_from_[k];
        if (!writes.empty()) writes[rerun_index_[k]] = rerun_writes_[k];
    }
    RestingGroups& groups = settling_.groups();
    for (const size_t i : members_)
        if (groups.asleep(i) && groups.marked(i)) groups.start(i, bodies[i]);
    groups.wake_marked();
    active_.clear();
    for (size_t i = 0; i < bodies.size(); ++i)
        if (!groups.asleep(i) && (alone.empty() || !alone[i])) active_.push_back(static_cast<uint32_t>(i));
    groups_asleep_ = groups.any_asleep();
    note_awake_members();
}

void Frame::Impl::note_settled(const World& world) {
    // Asleep bodies stay settled and as they were: only the stepped ones can
    // change their standing.
    for (const uint32_t i : active_) settling_.settle(i, world.bodies[i], colliders_);
    // When nothing was stepped the groups stand as they were.
    if (!groups_allowed_) settling_.groups().forget();
    else if (!active_.empty()) settling_.form_groups(world.bodies, members_);
}

const FrameReport& Frame::Impl::step(World& world, const FrameOptions& opts) {
    report_.user_writes.clear();
    report_.completed.clear();
    // Asleep bodies (settle.hpp) are left alone. Tracking them costs a copy
    // of every body; it is done only while at least half of the bodies can
    // settle (rain with a third at rest, or a crowd of solids that can never
    // sleep, would pay for nothing).
    const bool track = settling_.tracking();
    if (track) {
        plan_sleep(world, opts);  // and the census
    } else {
        settling_.skip();  // step_bodies counts the bodies that can settle, all being awake
        groups_asleep_ = groups_forming_ = false;
        census(world.bodies, {}, true);  // the bodies are the frame-start scene
    }
    // Every per-entity step sees the scene as it was before the tweens ran
    // (without tweens, that is the bodies as they are: no copy needed).
    std::span<const Body> scene;
    if (world.tweens.empty()) {
        stats_.step[kStepTweens] = {0, world.bodies.size(), 0};
    } else {
        start_.assign(world.bodies.begin(), world.bodies.end());
        step_tweens(world, opts.dt);
        scene = start_;
    }
    run_waking(world.bodies, world.grid, opts, scene, {},
               track ? settling_.asleep_alone() : std::span<const uint8_t>());
    if (track) note_settled(world);
    settling_.end_frame(world.bodies.size());
    return report_;
}

Frame::Frame() : impl_(std::make_unique<Impl>()) {}
Frame::~Frame() = default;
Frame::Frame(Frame&&) noexcept = default;
Frame& Frame::operator=(Frame&&) noexcept = default;

const FrameReport& Frame::step(World& world, const FrameOptions& opts) {
    return impl_->step(world, opts);
}
void Frame::step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                         std::span<const Body> scene, std::span<FirstWrites> writes,
                         std::span<const uint8_t> asleep) {
    impl_->step_physics(bodies, grid, opts, scene, writes, asleep);
}
void Frame::step_physics_resting(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                                 std::span<const Body> scene, std::span<FirstWrites> writes,
                                 std::span<const uint8_t> asleep, std::span<const uint8_t> fit, bool keep) {
    impl_->step_physics_resting(bodies, grid, opts, scene, writes, asleep, fit, keep);
}
bool Frame::resting_asleep(size_t i) const { return impl_->settling_.groups().asleep(i); }
bool Frame::resting_grouped(size_t i) const { return impl_->settling_.groups().grouped(i); }
void Frame::form_resting_groups(std::span<const Body> bodies, std::span<const uint8_t> unchanged) {
    Impl& m = *impl_;
    // As step() does (note_settled): when nothing was stepped the groups
    // stand as they were.
    if (!m.groups_allowed_) m.settling_.groups().forget();
    else if (!m.active_.empty()) m.settling_.groups().form(bodies, m.members_, unchanged);
}
const FrameStats& Frame::stats() const { return impl_->stats_; }
FrameStats& Frame::stats() { return impl_->stats_; }
void Frame::note_pairs(PairLog* log) { impl_->overlay_log_ = impl_->contacts_.log = log; }
std::span<const std::pair<uint32_t, uint32_t>> Frame::contact_pairs() const {
    const Impl& m = *impl_;
    if (m.contact_bodies_ == 0) return {};
    const PairLog& log = m.overlay_log_ ? *m.overlay_log_ : m.frame_pairs_;
    return std::span<const std::pair<uint32_t, uint32_t>>(log).subspan(m.pairs_from_);
}
std::span<const uint8_t> Frame::contact_sides() const {
    const Impl& m = *impl_;
    if (m.contact_bodies_ == 0) return {};
    return m.frame_sides_;
}

}  // namespace ds
