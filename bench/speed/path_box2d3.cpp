// SPDX-License-Identifier: MIT
// The box2d3 path: the same scene in Box2D v3 (3.x, the C API: SoA solver
// sets, graph-coloured soft-step solver, continuous collision), built only
// when CMake is given DOWNSTROKE_BENCH_BOX2D3_ROOT. It maps a scene exactly
// as path_box2d.cpp does for Box2D 2.4: 1 m = 32 px, gravity 112.5 m/s²,
// movers dynamic boxes with rotation locked (density 1, friction 0,
// restitution 0), bullets in the bullets scene, solid tiles as static boxes
// (one per maximal rectangle of equal row runs), pillars static, bodies that
// are not solid in our model colliding with tiles only. Everything else is
// v3's default: 4 substeps, sleeping on, continuous on. `workers` is 1 (no
// task callbacks: the caller's thread does all) or more (v3's own
// scheduler, with that many threads).
//
// This file sees v3's <box2d/box2d.h> through its own include directory
// (bench/CMakeLists.txt), never Debian's 2.4 header of the same name.
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
// v3's recommended substep count (b2World_Step's documentation).
constexpr int kSubsteps = 4;
constexpr uint64_t kTiles = 0x0001, kSolid = 0x0002, kGhost = 0x0004, kEnemy = 0x0008, kSensor = 0x0010;
// As in path_box2d.cpp: a solid meets tiles, solids, enemies and sensors.
constexpr uint64_t kSolidMask = kTiles | kSolid | kEnemy | kSensor;
// The rest scene is stepped until every body sleeps, at most this many
// frames (path_box2d.cpp's bound).
constexpr int kMaxSettleFrames = 240;

float m(double px) { return static_cast<float>(px / kPxPerM); }
float mps(double px_per_frame) { return static_cast<float>(px_per_frame * kHz / kPxPerM); }

void add_box(b2BodyId body, double x, double y, double w, double h, uint64_t category, uint64_t mask,
             float density) {
    const b2Vec2 origin = b2Body_GetPosition(body);
    // Relative to the body's position.
    const b2Polygon box = b2MakeOffsetBox(m(w / 2), m(h / 2),
                                          b2Vec2{m(x + w / 2) - origin.x, m(y + h / 2) - origin.y}, b2Rot_identity);
    b2ShapeDef sd = b2DefaultShapeDef();
    sd.isSensor = category == kSensor;
    // v3 reports sensor overlaps only between shapes that both ask for them;
    // 2.4 always found them, so every shape asks.
    sd.enableSensorEvents = true;
    sd.density = density;
    sd.material.friction = 0;
    sd.material.restitution = 0;
    sd.filter.categoryBits = category;
    sd.filter.maskBits = mask;
    b2CreatePolygonShape(body, &sd, &box);
}

struct Mover {
    b2BodyId body;
    float rvx, rvy;  // m/s; 0 = that axis does not bounce
};

// path_box2d.cpp's bounce update, through the v3 API.
void bounce(std::vector<Mover>& movers) {
    for (Mover& mv : movers) {
        if (mv.rvx == 0 && mv.rvy == 0) continue;
        b2Vec2 v = b2Body_GetLinearVelocity(mv.body);
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
        if (turned) b2Body_SetLinearVelocity(mv.body, v);
    }
}

// Owns a v3 world: destroyed on every way out of run_box2d3.
struct WorldOwner {
    b2WorldId id;
    ~WorldOwner() { b2DestroyWorld(id); }
};

}  // namespace

PathResult run_box2d3(const Scene& scene, const RunConfig& cfg, int workers) {
    PathResult r;
    const int64_t t_setup = now_ns();
    b2WorldDef wd = b2DefaultWorldDef();
    wd.gravity = b2Vec2{0.0f, 1.0f * kHz * kHz / kPxPerM};
    wd.workerCount = workers;
    const WorldOwner world{b2CreateWorld(&wd)};
    b2BodyDef ground_def = b2DefaultBodyDef();
    const b2BodyId ground = b2CreateBody(world.id, &ground_def);
    for (const Rect& rect : tile_rects(scene))
        add_box(ground, static_cast<double>(rect.c0) * scene.tile, static_cast<double>(rect.r0) * scene.tile,
                static_cast<double>(rect.c1 - rect.c0 + 1) * scene.tile,
                static_cast<double>(rect.r1 - rect.r0 + 1) * scene.tile, kTiles, ~uint64_t{0}, 0);
    std::vector<Mover> movers;
    for (const SceneBody& sb : scene.bodies) {
        b2BodyDef bd = b2DefaultBodyDef();
        bd.position = b2Vec2{m(static_cast<double>(sb.x) + sb.w / 2.0), m(static_cast<double>(sb.y) + sb.h / 2.0)};
        if (sb.immovable) {
            bd.type = b2_staticBody;
            const b2BodyId body = b2CreateBody(world.id, &bd);
            add_box(body, static_cast<double>(sb.x), static_cast<double>(sb.y), static_cast<double>(sb.w),
                    static_cast<double>(sb.h), sb.sensor ? kSensor : kSolid, kSolid | kEnemy, 0);
            continue;
        }
        bd.type = b2_dynamicBody;
        bd.motionLocks.angularZ = true;
        bd.isBullet = scene.bullets;
        bd.gravityScale = sb.gravity ? 1.0f : 0.0f;
        bd.linearVelocity = b2Vec2{mps(static_cast<double>(sb.vx)), mps(static_cast<double>(sb.vy))};
        const b2BodyId body = b2CreateBody(world.id, &bd);
        add_box(body, static_cast<double>(sb.x), static_cast<double>(sb.y), static_cast<double>(sb.w),
                static_cast<double>(sb.h), !sb.solid ? kGhost : sb.enemy ? kEnemy : kSolid,
                sb.solid ? kSolidMask : kTiles, 1.0f);
        movers.push_back({body, mps(static_cast<double>(sb.rvx)), mps(static_cast<double>(sb.rvy))});
    }
    const float dt = 1.0f / kHz;
    if (scene.settle_box2d)
        for (int i = 0; i < kMaxSettleFrames && b2World_GetAwakeBodyCount(world.id) > 0; ++i)
            b2World_Step(world.id, dt, kSubsteps);
    r.setup_ms = static_cast<double>(now_ns() - t_setup) / 1e6;
    FrameGuard guard(cfg.max_frame_ms, cfg.budget_ms);
    const bool debug = std::getenv("DS_BENCH_DEBUG") != nullptr;
    for (int i = 0; i < cfg.warmup + cfg.frames; ++i) {
        const int64_t t0 = now_ns();
        b2World_Step(world.id, dt, kSubsteps);
        const int64_t t1 = now_ns();
        const double ms = static_cast<double>(t1 - t0) / 1e6;
        if (i >= cfg.warmup) r.frame_ms.push_back(ms);
        r.spent_ms += ms;
        if (debug) {
            const b2Profile p = b2World_GetProfile(world.id);
            std::fprintf(stderr,
                         "box2d3 step %.3f ms: pairs %.3f collide %.3f solve %.3f refit %.3f bullets %.3f "
                         "sleep %.3f, %d awake bodies\n",
                         p.step, p.pairs, p.collide, p.solve, p.refit, p.bullets, p.sleepIslands,
                         b2World_GetAwakeBodyCount(world.id));
        }
        if (scene.bounce) bounce(movers);
        if (!guard.keep_going(ms, static_cast<int>(r.frame_ms.size()))) break;
    }
    r.skipped = guard.skip_reason();
    size_t k = 0;
    r.checksum = 0;
    for (const SceneBody& sb : scene.bodies) {
        if (sb.immovable) continue;
        const b2Vec2 c = b2Body_GetPosition(movers[k++].body);
        r.checksum += (c.x * kPxPerM - sb.w / 2.0) + 3 * (c.y * kPxPerM - sb.h / 2.0);
    }
    return r;
}

std::string box2d3_version() {
    const b2Version v = b2GetVersion();
    return std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.revision);
}

}  // namespace bench
