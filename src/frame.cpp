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

void Frame::step_physics(std::span<Body> bodies, const TileGrid* grid, const FrameOptions& opts,
                         std::span<const Body> scene) {
    if (scene.empty()) {
        start_.assign(bodies.begin(), bodies.end());
        scene = start_;
    }
    supporters_.clear();
    support_slot_.assign(bodies.size(), -1);
    for (size_t i = 0; i < scene.size(); ++i) {
        if (!scene[i].solid || scene[i].skips(kSkipEntityCollisions)) continue;
        support_slot_[i] = std::ssize(supporters_);
        supporters_.push_back(scene[i]);
    }
    for (size_t i = 0; i < bodies.size(); ++i) {
        Body& b = bodies[i];
        apply_acceleration(b);
        apply_gravity(b);
        apply_velocity_x(b);
        resolve_tile_collisions_x(b, grid, opts.mode);
        apply_velocity_y(b);
        resolve_tile_collisions_y(b, grid, opts.mode);
        detect_on_solid(b, supporters_, support_slot_[i], grid);
    }
    resolve_entity_collisions(bodies);
    sync_groups(bodies);
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
