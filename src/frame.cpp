#include "frame.hpp"

#include <algorithm>

#include "contacts.hpp"
#include "groups.hpp"
#include "steps.hpp"

namespace ds {

Num* body_field(Body& b, uint32_t key) {
    switch (key) {
        case kKeyX: return &b.x;
        case kKeyY: return &b.y;
        case kKeyWidth: return &b.w;
        case kKeyHeight: return &b.h;
        case kKeyVx: return &b.vx;
        case kKeyVy: return &b.vy;
        case kKeyAy: return &b.ay;
        case kKeyLocalX: return &b.local_x;
        case kKeyLocalY: return &b.local_y;
        default: return nullptr;
    }
}

void Frame::step_tweens(World& world, double dt) {
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
}

namespace {

// Runs one per-entity step; when it may write a field the entity lacks,
// compares around it so the first write is logged.
template <class Step>
void logged(Body& b, FirstWrites* w, uint32_t may_write, Step&& step) {
    if (w == nullptr || (w->watched & may_write) == 0) {
        step(b);
        return;
    }
    const Body before = b;
    step(b);
    w->note(changed_fields(before, b) & may_write);
}

}  // namespace

void Frame::step_bodies(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                        std::span<FirstWrites> writes) {
    const CollisionMode mode = opts.mode;
    // A handful of supporters are cheaper to scan than to index.
    const bool indexed = supporters_.size() >= 32;
    if (indexed) support_index_.build(supporters_);
    for (size_t i = 0; i < bodies.size(); ++i) {
        Body& b = bodies[i];
        FirstWrites* w = writes.empty() ? nullptr : &writes[i];
        // What each step can write given the body as it is: acceleration
        // resets only a non-zero ay, tile steps do nothing at zero speed.
        const auto unless_zero = [](Num n, uint32_t fields) { return n.v != 0 ? fields : 0u; };
        logged(b, w, kFieldVy | unless_zero(b.ay, kFieldAy), apply_acceleration);
        logged(b, w, kFieldVy, apply_gravity);
        logged(b, w, kFieldX, apply_velocity_x);
        logged(b, w, unless_zero(b.vx, kFieldX | kFieldVx),
               [&](Body& c) { resolve_tile_collisions_x(c, grid, mode); });
        logged(b, w, kFieldY, apply_velocity_y);
        logged(b, w, unless_zero(b.vy, kFieldY | kFieldVy),
               [&](Body& c) { resolve_tile_collisions_y(c, grid, mode); });
        logged(b, w, kFieldOnGround, [&](Body& c) {
            if (indexed) detect_on_solid(c, supporters_, support_index_, support_slot_[i], grid);
            else detect_on_solid(c, supporters_, support_slot_[i], grid);
        });
    }
}

template <class Bulk>
void Frame::logged_bulk(std::span<Body> bodies, std::span<FirstWrites> writes, uint32_t may_write,
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

void Frame::step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                         std::span<const Body> scene, std::span<FirstWrites> writes) {
    // Ground detection reads only the supporters, copied out below before
    // any body moves: with no separate frame-start scene, the bodies as they
    // are now are that scene.
    if (scene.empty()) scene = bodies;
    supporters_.clear();
    support_slot_.assign(bodies.size(), -1);
    for (size_t i = 0; i < scene.size(); ++i) {
        if (!scene[i].solid || scene[i].skips(kSkipEntityCollisions)) continue;
        support_slot_[i] = std::ssize(supporters_);
        supporters_.push_back(scene[i]);
    }
    step_bodies(bodies, grid, opts, writes);
    logged_bulk(bodies, writes, kFieldX | kFieldY | kFieldVx | kFieldVy, resolve_entity_collisions);
    logged_bulk(bodies, writes, kFieldX | kFieldY, sync_groups);
}

const FrameReport& Frame::step(World& world, const FrameOptions& opts) {
    report_.user_writes.clear();
    report_.completed.clear();
    // Every per-entity step sees the scene as it was before the tweens ran.
    start_.assign(world.bodies.begin(), world.bodies.end());
    step_tweens(world, opts.dt);
    step_physics(world.bodies, world.grid, opts, start_);
    return report_;
}

}  // namespace ds
