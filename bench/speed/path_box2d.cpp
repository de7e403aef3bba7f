// SPDX-License-Identifier: MIT
// The box2d path: the same scene in Box2D 2.4 as a speed comparison.
// Units: 1 m = 32 px, so 8 px boxes are 0.25 m and a 60 px/frame bullet
// moves 1.875 m per step, under Box2D's 2 m per-step cap (b2_maxTranslation);
// gravity 1 px/frame² is 1 × 60² / 32 = 112.5 m/s². Movers are dynamic,
// fixed-rotation boxes (density 1, friction 0, restitution 0); the solid
// tiles are static boxes, one per maximal rectangle of equal row runs;
// pillars are static bodies. Bodies that are not solid in our model collide
// with tiles only (collision filtering). 60 Hz: Step(1/60, 8, 3). Sleeping
// is off except in the rest scene; `discrete` turns continuous collision off.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "common/timing.hpp"
#include "speed/paths.hpp"
#include "speed/tile_rects.hpp"

namespace bench {

namespace {

constexpr float kPxPerM = 32.0f;
constexpr float kHz = 60.0f;
constexpr uint16 kTiles = 0x0001, kSolid = 0x0002, kGhost = 0x0004, kEnemy = 0x0008, kSensor = 0x0010;
// What a solid body collides with: tiles and solids, and the enemies and
// sensors of the scenes that have them (crowd-categories, crowd-sensors).
constexpr uint16 kSolidMask = kTiles | kSolid | kEnemy | kSensor;

float m(double px) { return static_cast<float>(px / kPxPerM); }
float mps(double px_per_frame) { return static_cast<float>(px_per_frame * kHz / kPxPerM); }

void add_box(b2Body* body, double x, double y, double w, double h, uint16 category, uint16 mask,
             float density) {
    b2PolygonShape shape;
    // Relative to the body's position.
    shape.SetAsBox(m(w / 2), m(h / 2), b2Vec2(m(x + w / 2) - body->GetPosition().x, m(y + h / 2) - body->GetPosition().y), 0);
    b2FixtureDef fd;
    fd.shape = &shape;
    fd.isSensor = category == kSensor;
    fd.density = density;
    fd.friction = 0;
    fd.restitution = 0;
    fd.filter.categoryBits = category;
    fd.filter.maskBits = mask;
    body->CreateFixture(&fd);
}

struct Mover {
    b2Body* body;
    float rvx, rvy;  // m/s; 0 = that axis does not bounce
};

void bounce(std::vector<Mover>& movers) {
    for (Mover& mv : movers) {
        if (mv.rvx == 0 && mv.rvy == 0) continue;
        b2Vec2 v = mv.body->GetLinearVelocity();
        bool turned = false;
        if (mv.rvx != 0 && std::fabs(v.x) < 0.1f * std::fabs(mv.rvx)) {
            mv.rvx = -mv.rvx;
            v.x = mv.rvx;
            turned = true;
        }
        if (mv.rvy != 0 && std::fabs(v.y) < 0.1f * std::fabs(mv.rvy)) {
            mv.rvy = -mv.rvy;
            v.y = mv.rvy;
            turned = true;
        }
        if (turned) mv.body->SetLinearVelocity(v);
    }
}

}  // namespace

PathResult run_box2d(const Scene& scene, const RunConfig& cfg, bool discrete) {
    PathResult r;
    const int64_t t_setup = now_ns();
    b2World world(b2Vec2(0.0f, 1.0f * kHz * kHz / kPxPerM));
    // Our engine steps every body every frame; so does Box2D here, except in
    // the rest scene, where going to sleep is Box2D's way of being settled.
    world.SetAllowSleeping(scene.settle_box2d);
    world.SetContinuousPhysics(!discrete);
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    for (const Rect& rect : tile_rects(scene))
        add_box(ground, static_cast<double>(rect.c0) * scene.tile, static_cast<double>(rect.r0) * scene.tile,
                static_cast<double>(rect.c1 - rect.c0 + 1) * scene.tile,
                static_cast<double>(rect.r1 - rect.r0 + 1) * scene.tile, kTiles, 0xFFFF, 0);
    std::vector<Mover> movers;
    for (const SceneBody& sb : scene.bodies) {
        b2BodyDef bd;
        bd.position.Set(m(static_cast<double>(sb.x) + sb.w / 2.0), m(static_cast<double>(sb.y) + sb.h / 2.0));
        if (sb.immovable) {
            bd.type = b2_staticBody;
            b2Body* body = world.CreateBody(&bd);
            add_box(body, static_cast<double>(sb.x), static_cast<double>(sb.y), static_cast<double>(sb.w),
                    static_cast<double>(sb.h), sb.sensor ? kSensor : kSolid,
                    sb.sensor ? (kSolid | kEnemy) : (kSolid | kEnemy), 0);
            continue;
        }
        bd.type = b2_dynamicBody;
        bd.fixedRotation = true;
        bd.bullet = scene.bullets;
        bd.gravityScale = sb.gravity ? 1.0f : 0.0f;
        bd.linearVelocity.Set(mps(static_cast<double>(sb.vx)), mps(static_cast<double>(sb.vy)));
        b2Body* body = world.CreateBody(&bd);
        add_box(body, static_cast<double>(sb.x), static_cast<double>(sb.y), static_cast<double>(sb.w),
                static_cast<double>(sb.h), !sb.solid ? kGhost : sb.enemy ? kEnemy : kSolid,
                sb.solid ? kSolidMask : kTiles, 1.0f);
        movers.push_back({body, mps(static_cast<double>(sb.rvx)), mps(static_cast<double>(sb.rvy))});
    }
    const float dt = 1.0f / kHz;
    if (scene.settle_box2d) {
        // "At rest" for Box2D: settled and asleep, as our rest scene is settled.
        for (int i = 0; i < 240; ++i) {
            world.Step(dt, 8, 3);
            bool awake = false;
            for (const Mover& mv : movers) awake = awake || mv.body->IsAwake();
            if (!awake) break;
        }
    }
    r.setup_ms = static_cast<double>(now_ns() - t_setup) / 1e6;
    FrameGuard guard(cfg.max_frame_ms, cfg.budget_ms);
    const bool debug = std::getenv("DS_BENCH_DEBUG") != nullptr;
    for (int i = 0; i < cfg.warmup + cfg.frames; ++i) {
        const int64_t t0 = now_ns();
        world.Step(dt, 8, 3);
        const int64_t t1 = now_ns();
        const double ms = static_cast<double>(t1 - t0) / 1e6;
        if (i >= cfg.warmup) r.frame_ms.push_back(ms);
        r.spent_ms += ms;
        if (debug) {
            const b2Profile& p = world.GetProfile();
            std::fprintf(stderr, "box2d step %.2f ms: collide %.2f solve %.2f broadphase %.2f toi %.2f, %d contacts\n",
                         p.step, p.collide, p.solve, p.broadphase, p.solveTOI, world.GetContactCount());
        }
        if (scene.bounce) bounce(movers);
        if (!guard.keep_going(ms, static_cast<int>(r.frame_ms.size()))) break;
    }
    r.skipped = guard.skip_reason();
    size_t k = 0;
    r.checksum = 0;
    for (const SceneBody& sb : scene.bodies) {
        if (sb.immovable) continue;
        const b2Vec2 c = movers[k++].body->GetPosition();
        r.checksum += (c.x * kPxPerM - sb.w / 2.0) + 3 * (c.y * kPxPerM - sb.h / 2.0);
    }
    return r;
}

std::string box2d_version() {
    const std::string linked = std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) +
                               "." + std::to_string(b2_version.revision);
    const std::string package = DS_BENCH_BOX2D_PKG_VERSION;
    if (package.empty() || package == linked) return linked;
    return package + " (pkg-config; its b2_version says " + linked + ")";
}

}  // namespace bench
