// SPDX-License-Identifier: MIT
// One whole engine pass (semantics §5): tweens, per-entity steps against the
// frame-start scene, entity push-apart, groups.
#include <algorithm>
#include <memory>
#include <new>
#include <vector>

#include "detail/first_writes.hpp"
#include "frame.hpp"
#include "support.hpp"

using namespace dst;
using ds::CollisionMode;
using ds::Frame;
using ds::FrameOptions;
using ds::FrameReport;
using ds::TweenTrack;
using ds::World;

namespace {

FrameOptions opts(double dt = 1000.0 / 60.0, CollisionMode mode = CollisionMode::Swept) {
    FrameOptions o;
    o.dt = dt;
    o.mode = mode;
    return o;
}

Body player(double x, double y) {
    Body b = box(x, y, 16, 16);
    b.gravity = true;
    b.solid = true;
    return b;
}

TweenTrack track(uint32_t body, std::vector<ds::TweenProp> props, double duration,
                 double delay = 0, int64_t repeat = 0, bool yoyo = false,
                 ds::Ease ease = ds::Ease::Linear) {
    TweenTrack t;
    t.body = body;
    t.props = std::move(props);
    t.timing.duration = duration;
    t.timing.delay = delay;
    t.timing.repeat = repeat;
    t.timing.yoyo = yoyo;
    t.ease = ease;
    t.elapsed = 0;
    return t;
}

ds::TweenProp tp(uint32_t key, ds::Num start, ds::Num end) {
    ds::TweenProp p;
    p.key = key;
    p.start = start;
    p.end = end;
    return p;
}

}  // namespace

TEST_SUITE("frame") {

TEST_CASE("body_field maps physics keys to body fields and user keys to nothing") {
    Body b;
    CHECK(ds::body_field(b, ds::kKeyX) == &b.x);
    CHECK(ds::body_field(b, ds::kKeyY) == &b.y);
    CHECK(ds::body_field(b, ds::kKeyWidth) == &b.w);
    CHECK(ds::body_field(b, ds::kKeyHeight) == &b.h);
    CHECK(ds::body_field(b, ds::kKeyVx) == &b.vx);
    CHECK(ds::body_field(b, ds::kKeyVy) == &b.vy);
    CHECK(ds::body_field(b, ds::kKeyAy) == &b.ay);
    CHECK(ds::body_field(b, ds::kKeyLocalX) == &b.local_x);
    CHECK(ds::body_field(b, ds::kKeyLocalY) == &b.local_y);
    CHECK(ds::body_field(b, ds::kFirstUserKey) == nullptr);
    CHECK(ds::body_field(b, ds::kFirstUserKey + 1) == nullptr);
    CHECK(ds::body_field(b, 1000) == nullptr);
}

TEST_CASE("FrameOptions default to swept collisions") {
    CHECK(FrameOptions{}.mode == CollisionMode::Swept);
    CHECK(FrameOptions{}.dt > 0);
}

// ---- motion -----------------------------------------------------------------

TEST_CASE("a falling body lands on a tile floor") {
    const auto g = grid({"....", "....", "....", "####"});
    World w;
    w.grid = &g;
    Body b = player(16, 30);
    b.vy = I(2);
    w.bodies = {b};
    Frame f;
    f.step(w, opts());
    const Body& r = w.bodies[0];
    // vy 2 → 3; y 30 → 33, overlapping row 3 → snapped to 48 - 16
    CHECK_EXACT(r.y, 32);
    CHECK_EXACT(r.vy, 0);
    CHECK_EXACT(r.x, 16);
    CHECK_EXACT(r.vx, 0);
    CHECK(r.on_ground);
    CHECK(ds::changed_fields(b, r) == (ds::kFieldY | ds::kFieldVy | ds::kFieldOnGround));
    // resting: the next frames change nothing at all
    const Body rest = w.bodies[0];
    f.step(w, opts());
    CHECK(same_body(w.bodies[0], rest));
    f.step(w, opts());
    CHECK(same_body(w.bodies[0], rest));
}

// ---- first writes to absent fields -------------------------------------------

TEST_CASE("step_physics logs first writes to absent fields in step order") {
    SUBCASE("gravity writes vy, then velocity-x x, then velocity-y y") {
        Body b = box(0, 0, 4, 4);
        b.gravity = true;
        b.vx = I(1);
        std::vector<Body> bodies{b};
        std::vector<ds::FirstWrites> writes{{.watched = ds::kFieldX | ds::kFieldY | ds::kFieldVy |
                                                       ds::kFieldAy | ds::kFieldOnGround}};
        Frame f;
        f.step_physics(bodies, nullptr, opts(), {}, writes);
        REQUIRE(writes[0].count == 3);
        CHECK((1u << writes[0].order[0]) == ds::kFieldVy);
        CHECK((1u << writes[0].order[1]) == ds::kFieldX);
        CHECK((1u << writes[0].order[2]) == ds::kFieldY);
        CHECK(writes[0].watched == (ds::kFieldAy | ds::kFieldOnGround));
    }
    SUBCASE("a write later undone stays logged: vy 0 → 1 by gravity → 0 on landing") {
        const auto g = grid({"....", "####"});
        Body b = player(16, 0);
        b.solid = false;
        b.on_ground = true;
        std::vector<Body> bodies{b};
        std::vector<ds::FirstWrites> writes{{.watched = ds::kFieldVy | ds::kFieldVx}};
        Frame f;
        f.step_physics(bodies, &g, opts(), {}, writes);
        CHECK_EXACT(bodies[0].vy, 0);
        CHECK(ds::changed_fields(b, bodies[0]) == 0);
        REQUIRE(writes[0].count == 1);
        CHECK((1u << writes[0].order[0]) == ds::kFieldVy);
        CHECK(writes[0].written() == ds::kFieldVy);
    }
    SUBCASE("push-apart writes x then vx in one step (bit order)") {
        std::vector<Body> bodies{solid_box(0, 0, 16, 16), solid_box(10, 2, 16, 16)};
        std::vector<ds::FirstWrites> writes(2, {.watched = ds::kFieldVx});
        Frame f;
        f.step_physics(bodies, nullptr, opts(), {}, writes);
        CHECK_EXACT(bodies[0].vx, -1);
        CHECK_EXACT(bodies[1].vx, 1);
        CHECK(writes[0].count == 1);
        CHECK(writes[1].count == 1);
        CHECK(writes[1].written() == ds::kFieldVx);
    }
}

TEST_CASE("the step order: acceleration, gravity, x, tile x, y, tile y, on-solid") {
    SUBCASE("a jump: vy = 0 - 15 + 1") {
        World w;
        Body b = player(0, 100);
        b.ay = I(-15);
        b.on_ground = true;
        w.bodies = {b};
        Frame f;
        f.step(w, opts());
        CHECK_EXACT(w.bodies[0].vy, -14);
        CHECK_EXACT(w.bodies[0].y, 86);
        CHECK_EXACT(w.bodies[0].ay, 0);
        CHECK_FALSE(w.bodies[0].on_ground);
    }
    SUBCASE("x is resolved before y moves: sliding along a floor is not a wall hit") {
        const auto g = grid({"....", "####"});
        World w;
        w.grid = &g;
        Body b = box(0, 0, 16, 16);
        b.vx = I(4);
        b.vy = I(4);
        w.bodies = {b};
        Frame f;
        f.step(w, opts());
        CHECK_EXACT(w.bodies[0].x, 4);
        CHECK_EXACT(w.bodies[0].vx, 4);
        CHECK_EXACT(w.bodies[0].y, 0);
        CHECK_EXACT(w.bodies[0].vy, 0);
        CHECK_FALSE(w.bodies[0].on_ground);  // gravity? is false: never written
    }
    SUBCASE("flonum velocities give flonum positions") {
        World w;
        Body b = player(0, 0);
        b.vx = F(0.5);
        w.bodies = {b};
        Frame f;
        f.step(w, opts());
        CHECK_FLONUM(w.bodies[0].x, 0.5);
        CHECK_EXACT(w.bodies[0].y, 1);
        CHECK_EXACT(w.bodies[0].vy, 1);
    }
}

TEST_CASE("the collision mode reaches the tile steps") {
    const auto g = grid({".....#.............."});
    Body b = box(0, 0, 16, 16);
    b.vx = I(160);
    SUBCASE("swept") {
        World w;
        w.grid = &g;
        w.bodies = {b};
        Frame f;
        f.step(w, opts(16, CollisionMode::Swept));
        CHECK_EXACT(w.bodies[0].x, 64);
        CHECK_EXACT(w.bodies[0].vx, 0);
    }
    SUBCASE("discrete") {
        World w;
        w.grid = &g;
        w.bodies = {b};
        Frame f;
        f.step(w, opts(16, CollisionMode::Discrete));
        CHECK_EXACT(w.bodies[0].x, 160);
        CHECK_EXACT(w.bodies[0].vx, 160);
    }
}

// ---- standing on entities ---------------------------------------------------

TEST_CASE("an entity standing on a platform entity") {
    World w;
    w.bodies = {wall_box(0, 64, 64, 16), player(16, 48)};
    const Body start = w.bodies[1];
    Frame f;
    f.step(w, opts());
    const Body& p = w.bodies[1];
    // gravity pulls it 1 px into the platform; on-solid sees the platform's top
    // within tolerance; push-apart lifts it back out and zeroes vy
    CHECK_EXACT(p.y, 48);
    CHECK_EXACT(p.vy, 0);
    CHECK_EXACT(p.x, 16);
    CHECK(p.on_ground);
    CHECK(ds::changed_fields(start, p) == ds::kFieldOnGround);
    CHECK(same_body(w.bodies[0], wall_box(0, 64, 64, 16)));
    // and it stays there, frame after frame, unchanged
    const Body rest = w.bodies[1];
    for (int i = 0; i < 5; ++i) {
        f.step(w, opts());
        CHECK(same_body(w.bodies[1], rest));
    }
}

TEST_CASE("skip bits inside a frame: a ghost sinks into the platform but is still held up") {
    // 'entity-collisions on the mover: no push-apart, but on-solid only asks
    // whether the *supporting* body is a ghost
    World w;
    Body p = player(16, 48);
    p.skip = ds::kSkipEntityCollisions;
    w.bodies = {wall_box(0, 64, 64, 16), p};
    Frame f;
    f.step(w, opts());
    CHECK_EXACT(w.bodies[1].y, 49);
    CHECK_EXACT(w.bodies[1].vy, 1);
    CHECK(w.bodies[1].on_ground);
    // 'on-solid on the mover: the flag keeps its old value
    Body q = player(16, 48);
    q.skip = ds::kSkipOnSolid;
    w.bodies = {wall_box(0, 64, 64, 16), q};
    f.step(w, opts());
    CHECK_EXACT(w.bodies[1].y, 48);
    CHECK_EXACT(w.bodies[1].vy, 0);
    CHECK_FALSE(w.bodies[1].on_ground);
    // 'gravity and 'velocity-y: it hangs in the air
    Body r = player(16, 0);
    r.vy = I(3);
    r.skip = ds::kSkipGravity | ds::kSkipVelocityY;
    w.bodies = {r};
    f.step(w, opts());
    CHECK_EXACT(w.bodies[0].y, 0);
    CHECK_EXACT(w.bodies[0].vy, 3);
}

TEST_CASE("on-solid reads the frame-start scene, not bodies already moved") {
    // A: a solid platform moving down 10 px/frame, listed first so it moves first.
    // B: a body falling at the same speed, feet on A's frame-start top.
    Body a = solid_box(0, 64, 64, 16);
    a.vy = I(10);
    Body b = box(16, 38, 16, 16);
    b.gravity = true;
    b.vy = I(9);
    for (bool a_first : {true, false}) {
        CAPTURE(a_first);
        World w;
        w.bodies = a_first ? std::vector<Body>{a, b} : std::vector<Body>{b, a};
        const size_t ia = a_first ? 0 : 1, ib = a_first ? 1 : 0;
        Frame f;
        f.step(w, opts());
        CHECK_EXACT(w.bodies[ia].y, 74);
        CHECK_EXACT(w.bodies[ib].vy, 10);
        CHECK_EXACT(w.bodies[ib].y, 48);  // feet at 64: A's top at the frame start
        CHECK(w.bodies[ib].on_ground);
    }
}

TEST_CASE("on-solid in a frame never counts the body's own slot") {
    // a 3 px tall solid body would rest on its own frame-start copy
    World w;
    Body b = box(0, 0, 16, 3);
    b.gravity = true;
    b.solid = true;
    w.bodies = {b};
    Frame f;
    f.step(w, opts());
    CHECK_EXACT(w.bodies[0].y, 1);
    CHECK_FALSE(w.bodies[0].on_ground);
}

TEST_CASE("on-solid in a frame skips bodies with the same id") {
    Body plat = solid_box(0, 64, 64, 16);
    plat.id = 5;
    Body b = box(16, 48, 16, 16);
    b.gravity = true;
    b.id = 5;
    World w;
    w.bodies = {plat, b};
    Frame f;
    f.step(w, opts());
    CHECK_EXACT(w.bodies[1].y, 49);
    CHECK_FALSE(w.bodies[1].on_ground);
    b.id = 6;
    w.bodies = {plat, b};
    f.step(w, opts());
    CHECK(w.bodies[1].on_ground);
}

// ---- entities and groups ----------------------------------------------------

TEST_CASE("entity push-apart runs after the motion steps, then groups follow") {
    // the origin walks into a wall and is pushed back; its member follows the
    // pushed position, not the walked one
    Body origin = solid_box(0, 0, 16, 16);
    origin.vx = I(5);
    origin.group = 1;
    origin.group_origin = true;
    Body member = box(100, 100, 8, 8);
    member.group = 1;
    member.local_x = I(0);
    member.local_y = I(-20);
    World w;
    w.bodies = {origin, wall_box(20, 0, 16, 16), member};
    Frame f;
    f.step(w, opts());
    CHECK_EXACT(w.bodies[0].x, 4);  // moved to 5, overlapped the wall by 1, pushed to 20 - 16
    CHECK_EXACT(w.bodies[0].vx, 0);
    CHECK_EXACT(w.bodies[2].x, 4);
    CHECK_EXACT(w.bodies[2].y, -20);
}

TEST_CASE("two movers meeting in a frame are pushed apart") {
    Body a = solid_box(0, 0, 16, 16);
    a.vx = I(3);
    Body b = solid_box(20, 0, 16, 16);
    b.vx = I(-4);
    World w;
    w.bodies = {a, b};
    Frame f;
    f.step(w, opts());
    // a → 3, b → 16: overlap 3 on x, a moves 2 left, b 1 right
    CHECK_EXACT(w.bodies[0].x, 1);
    CHECK_EXACT(w.bodies[1].x, 17);
    CHECK_EXACT(w.bodies[0].vx, -1);
    CHECK_EXACT(w.bodies[1].vx, 1);
}

// ---- tweens -----------------------------------------------------------------

TEST_CASE("a tween drives x and a user key, and reports completion") {
    World w;
    w.bodies = {box(0, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyX, I(0), I(100)), tp(ds::kFirstUserKey, I(0), I(10))}, 100)};
    Frame f;
    const double xs[] = {25, 50, 75};
    for (double x : xs) {
        const FrameReport& rep = f.step(w, opts(25));
        CAPTURE(x);
        CHECK_FLONUM(w.bodies[0].x, x);
        REQUIRE(rep.user_writes.size() == 1);
        CHECK(rep.user_writes[0].body == 0);
        CHECK(rep.user_writes[0].key == ds::kFirstUserKey);
        CHECK_FLONUM(rep.user_writes[0].value, x / 10);
        CHECK(rep.completed.empty());
        REQUIRE(w.tweens.size() == 1);
        CHECK(w.tweens[0].elapsed == x);
    }
    const FrameReport& last = f.step(w, opts(25));
    CHECK_EXACT(w.bodies[0].x, 100);  // the target itself
    REQUIRE(last.user_writes.size() == 1);
    CHECK(last.user_writes[0].key == ds::kFirstUserKey);
    CHECK_EXACT(last.user_writes[0].value, 10);
    REQUIRE(last.completed.size() == 1);
    CHECK(last.completed[0] == 0);
    CHECK(w.tweens.empty());
    // the report is fresh every frame
    const FrameReport& after = f.step(w, opts(25));
    CHECK(after.user_writes.empty());
    CHECK(after.completed.empty());
    CHECK_EXACT(w.bodies[0].x, 100);
}

TEST_CASE("a tween overshooting its end in one frame finishes at the target") {
    World w;
    w.bodies = {box(0, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyY, I(100), I(40))}, 10)};
    Frame f;
    const FrameReport& rep = f.step(w, opts(1000.0 / 60.0));
    CHECK_EXACT(w.bodies[0].y, 40);
    REQUIRE(rep.completed.size() == 1);
    CHECK(rep.completed[0] == 0);
    CHECK(w.tweens.empty());
}

TEST_CASE("tweens run before the motion steps") {
    World w;
    w.bodies = {box(0, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyVx, I(0), I(10))}, 100)};
    Frame f;
    f.step(w, opts(50));
    CHECK_FLONUM(w.bodies[0].vx, 5);
    CHECK_FLONUM(w.bodies[0].x, 5);  // exact 0 + flonum 5.0
}

TEST_CASE("the frame-start scene is taken before the tweens") {
    // semantics §5: every per-entity step sees the scene as it was when the frame
    // began. The platform is tweened from y 100 up to 64 this frame, but
    // ground detection reads it at 100: feet at 49 + 16 = 65, |65 - 100| > 4.
    World w;
    Body plat = solid_box(0, 100, 64, 16);
    Body p = box(16, 48, 16, 16);
    p.gravity = true;
    w.bodies = {plat, p};
    w.tweens = {track(0, {tp(ds::kKeyY, I(100), I(64))}, 10)};
    Frame f;
    const FrameReport& rep = f.step(w, opts(16));
    CHECK_EXACT(w.bodies[0].y, 64);
    REQUIRE(rep.completed.size() == 1);
    CHECK(rep.completed[0] == 0);
    CHECK_EXACT(w.bodies[1].y, 49);
    CHECK_FALSE(w.bodies[1].on_ground);
}

TEST_CASE("a tween waits out its delay without writing") {
    World w;
    w.bodies = {box(7, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyX, I(7), I(100)), tp(ds::kFirstUserKey + 3, I(0), I(1))},
                      100, 50)};
    Frame f;
    const FrameReport& rep = f.step(w, opts(20));
    CHECK(same_body(w.bodies[0], box(7, 0, 16, 16)));
    CHECK(rep.user_writes.empty());
    CHECK(rep.completed.empty());
    REQUIRE(w.tweens.size() == 1);
    CHECK(w.tweens[0].elapsed == 20);
    f.step(w, opts(40));  // elapsed 60: 10 ms into the cycle
    CHECK_FLONUM_APPROX(w.bodies[0].x, 16.3);
}

TEST_CASE("a yoyo tween goes there and back and ends at the start value") {
    World w;
    w.bodies = {box(0, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyX, I(0), I(100))}, 100, 0, 1, true)};
    Frame f;
    f.step(w, opts(50));
    CHECK_FLONUM(w.bodies[0].x, 50);
    f.step(w, opts(50));  // cycle 1 begins, reversed: at its start, the end value
    CHECK_FLONUM(w.bodies[0].x, 100);
    f.step(w, opts(50));
    CHECK_FLONUM(w.bodies[0].x, 50);
    const FrameReport& rep = f.step(w, opts(50));
    CHECK_EXACT(w.bodies[0].x, 0);
    REQUIRE(rep.completed.size() == 1);
    CHECK(w.tweens.empty());
}

TEST_CASE("a tween's easing is applied") {
    World w;
    w.bodies = {box(0, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyX, I(0), I(100))}, 100, 0, 0, false, ds::Ease::QuadIn)};
    Frame f;
    f.step(w, opts(50));
    CHECK_FLONUM(w.bodies[0].x, 25);
}

TEST_CASE("tweens on sizes and group offsets change those fields") {
    World w;
    w.bodies = {box(0, 0, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyWidth, I(16), I(32)), tp(ds::kKeyLocalY, I(0), I(-8))},
                      100)};
    const Body before = w.bodies[0];
    Frame f;
    f.step(w, opts(50));
    CHECK_FLONUM(w.bodies[0].w, 24);
    CHECK_FLONUM(w.bodies[0].local_y, -4);
    CHECK(ds::changed_fields(before, w.bodies[0]) == (ds::kFieldWidth | ds::kFieldLocalY));
}

TEST_CASE("several tweens finishing in one frame are all reported") {
    World w;
    w.bodies = {box(0, 0, 16, 16), box(0, 0, 16, 16), box(0, 0, 16, 16)};
    w.tweens = {track(2, {tp(ds::kKeyX, I(0), I(5))}, 10),
                track(0, {tp(ds::kKeyX, I(0), I(6))}, 10),
                track(1, {tp(ds::kKeyX, I(0), I(7))}, 1000)};
    Frame f;
    const FrameReport& rep = f.step(w, opts(16));
    std::vector<uint32_t> done = rep.completed;
    std::sort(done.begin(), done.end());
    CHECK(done == std::vector<uint32_t>{0, 2});
    REQUIRE(w.tweens.size() == 1);
    CHECK(w.tweens[0].body == 1);
    CHECK_EXACT(w.bodies[0].x, 6);
    CHECK_EXACT(w.bodies[2].x, 5);
    CHECK_FLONUM_APPROX(w.bodies[1].x, 0.112);
}

TEST_CASE("the 'tweens skip bit freezes a body's tween") {
    World w;
    Body b = box(0, 0, 16, 16);
    b.skip = ds::kSkipTweens;
    w.bodies = {b};
    w.tweens = {track(0, {tp(ds::kKeyX, I(0), I(100)), tp(ds::kFirstUserKey, I(0), I(1))}, 10)};
    Frame f;
    const FrameReport& rep = f.step(w, opts(50));
    CHECK(same_body(w.bodies[0], b));
    CHECK(rep.user_writes.empty());
    CHECK(rep.completed.empty());
    REQUIRE(w.tweens.size() == 1);
    CHECK(w.tweens[0].elapsed == 0);
}

// ---- skips, order independence, step_physics --------------------------------

TEST_CASE("a body skipping every step comes through a frame untouched") {
    const auto g = grid({"....", "####"});
    World w;
    w.grid = &g;
    Body b = player(8, 8);  // inside the floor, moving, with a pending jump
    b.vx = I(3);
    b.vy = I(5);
    b.ay = I(-15);
    b.skip = kEverySkip;
    w.bodies = {b, solid_box(10, 10, 16, 16)};
    w.tweens = {track(0, {tp(ds::kKeyY, I(0), I(100))}, 100)};
    Frame f;
    f.step(w, opts());
    CHECK(same_body(w.bodies[0], b));
    CHECK(w.tweens[0].elapsed == 0);
}

TEST_CASE("per-entity results do not depend on the order of bodies") {
    const auto g = grid({"........", "........", "........", "########"});
    Body plat = solid_box(0, 20, 40, 8);
    plat.vy = I(2);
    Body p = box(8, 4, 16, 16);
    p.gravity = true;
    p.vy = I(1);
    Body q = box(60, 10, 16, 16);
    q.gravity = true;
    q.vx = I(-2);
    q.vy = I(7);
    std::vector<Body> order1 = {plat, p, q}, order2 = {q, p, plat};
    World w1, w2;
    w1.grid = w2.grid = &g;
    w1.bodies = order1;
    w2.bodies = order2;
    Frame f1, f2;
    f1.step(w1, opts());
    f2.step(w2, opts());
    CHECK(same_body(w1.bodies[0], w2.bodies[2]));
    CHECK(same_body(w1.bodies[1], w2.bodies[1]));
    CHECK(same_body(w1.bodies[2], w2.bodies[0]));
    // p: vy 2, y 6, feet 22 vs plat's frame-start top 20: supported
    CHECK_EXACT(w1.bodies[1].y, 6);
    CHECK(w1.bodies[1].on_ground);
    // q: vy 8, y 18, feet 34: rows 1..2, no floor yet; not supported
    CHECK_EXACT(w1.bodies[2].x, 58);
    CHECK_EXACT(w1.bodies[2].y, 18);
    CHECK_FALSE(w1.bodies[2].on_ground);
}

TEST_CASE("step_physics is the frame without tweens") {
    const auto g = grid({"....", "....", "....", "####"});
    Body b = player(16, 30);
    b.vy = I(2);
    std::vector<Body> bodies = {wall_box(40, 40, 8, 8), b};
    Frame f;
    f.step_physics(bodies, &g, opts());
    CHECK_EXACT(bodies[1].y, 32);
    CHECK_EXACT(bodies[1].vy, 0);
    CHECK(bodies[1].on_ground);
    CHECK(same_body(bodies[0], wall_box(40, 40, 8, 8)));
    // no grid: nothing stops the fall
    std::vector<Body> free = {b};
    f.step_physics(free, nullptr, opts());
    CHECK_EXACT(free[0].y, 33);
    CHECK_EXACT(free[0].vy, 3);
    CHECK_FALSE(free[0].on_ground);
}

TEST_CASE("an empty world") {
    World w;
    Frame f;
    const FrameReport& rep = f.step(w, opts());
    CHECK(rep.completed.empty());
    CHECK(rep.user_writes.empty());
    CHECK(w.bodies.empty());
}

}  // TEST_SUITE

TEST_SUITE("frame") {

TEST_CASE("settled bodies are left alone, until something they depend on changes") {
    const auto g = grid({"....", "....", "####"});
    World w;
    w.grid = &g;
    Body b = box(16, 16, 16, 16);
    b.gravity = true;
    b.on_ground = true;
    w.bodies = {b, b};
    Frame f;
    for (int k = 0; k < 3; ++k) f.step(w, opts());
    CHECK(f.stats().step[ds::kStepGravity].processed == 0);  // both settled
    CHECK(same_body(w.bodies[0], b));
    // The caller moves one: it is stepped again (and falls back onto the floor).
    w.bodies[1].y = I(10);
    f.step(w, opts());
    CHECK(f.stats().step[ds::kStepGravity].processed == 1);
    CHECK_EXACT(w.bodies[1].y, 11);
    CHECK_EXACT(w.bodies[1].vy, 1);
    // A solid body appears: everyone might stand on it, so nobody is quiet.
    w.bodies.push_back(solid_box(100, 0, 8, 8));
    f.step(w, opts());
    CHECK(f.stats().step[ds::kStepGravity].processed == 2);
    // The map goes: the settled body falls.
    w.bodies.pop_back();
    for (int k = 0; k < 8; ++k) f.step(w, opts());
    CHECK(f.stats().step[ds::kStepGravity].processed == 0);
    w.grid = nullptr;
    f.step(w, opts());
    CHECK_EXACT(w.bodies[0].y, 17);
}

TEST_CASE("settled bodies wake when their grid is edited in place") {
    // Two boxes rest on the floor and settle; the tile under one is taken
    // out: the same grid, at the same address, in a new revision. Both wake
    // (the map is one of the conditions every settled body assumes); the one
    // over the hole falls, the other lands back where it was.
    auto g = grid({"....", "....", "####"});
    World w;
    w.grid = &g;
    Body b = box(16, 16, 16, 16);
    b.gravity = true;
    b.on_ground = true;
    Body c = b;
    c.x = I(48);
    w.bodies = {b, c};
    Frame f;
    for (int k = 0; k < 3; ++k) f.step(w, opts());
    REQUIRE(f.stats().step[ds::kStepGravity].processed == 0);  // both settled
    g.set_solid(1, 2, false);
    f.step(w, opts());
    CHECK(f.stats().step[ds::kStepGravity].processed == 2);
    CHECK_EXACT(w.bodies[0].y, 17);
    CHECK_EXACT(w.bodies[0].vy, 1);
    CHECK_FALSE(w.bodies[0].on_ground);
    CHECK(same_body(w.bodies[1], c));
    // A tile put back in place is noticed as well: hovering (gravity
    // skipped) over an empty row, a box settles off the ground, and stands
    // once a tile appears under its feet.
    auto open = grid({"....", "....", "...."});
    Body hover = box(0, 16, 16, 16);
    hover.gravity = true;
    hover.skip = ds::kSkipGravity;
    World h;
    h.grid = &open;
    h.bodies = {hover};
    Frame fh;
    for (int k = 0; k < 3; ++k) fh.step(h, opts());
    REQUIRE(fh.stats().step[ds::kStepOnSolid].processed == 0);
    REQUIRE_FALSE(h.bodies[0].on_ground);
    open.set_solid(0, 2, true);
    fh.step(h, opts());
    CHECK(h.bodies[0].on_ground);
}

TEST_CASE("settled bodies wake when a new grid is built where the old one was") {
    // The old grid is destroyed and a new one, without the floor, built in
    // the same storage: the World's pointer does not change, the revision
    // does, and the settled box falls.
    alignas(ds::TileGrid) unsigned char storage[sizeof(ds::TileGrid)];
    auto* floor = new (storage) ds::TileGrid(grid({"....", "....", "####"}));
    World w;
    w.grid = floor;
    Body b = box(16, 16, 16, 16);
    b.gravity = true;
    b.on_ground = true;
    w.bodies = {b};
    Frame f;
    for (int k = 0; k < 3; ++k) f.step(w, opts());
    REQUIRE(f.stats().step[ds::kStepGravity].processed == 0);
    std::destroy_at(floor);
    auto* bare = new (storage) ds::TileGrid(grid({"....", "....", "...."}));
    REQUIRE(static_cast<const void*>(bare) == static_cast<const void*>(w.grid));
    f.step(w, opts());
    CHECK(f.stats().step[ds::kStepGravity].processed == 1);
    CHECK_EXACT(w.bodies[0].y, 17);
    CHECK_EXACT(w.bodies[0].vy, 1);
    // Assigning a new grid over the old one is the same case.
    for (int k = 0; k < 8; ++k) f.step(w, opts());  // falls off the map, into the void
    *bare = grid({"....", "....", "####"});
    w.bodies = {b};
    for (int k = 0; k < 4; ++k) f.step(w, opts());  // one frame more: tracking resumes first
    REQUIRE(f.stats().step[ds::kStepGravity].processed == 0);
    *bare = grid({"....", "....", "...."});
    f.step(w, opts());
    CHECK_EXACT(w.bodies[0].y, 17);
    std::destroy_at(bare);
}

TEST_CASE("settled bodies are tracked once half of them end a frame still") {
    // Tracking which bodies settled costs a copy of each, so a frame starts
    // it only when at least half ended the last frame still. Four movers:
    // no tracking after the first frame. Then two stop: the untracked frame
    // counts them, the next starts tracking, the one after finds them
    // settled, and from then on they are not stepped.
    Body mover = box(0, 0, 8, 8), still = box(40, 0, 8, 8);
    mover.vx = I(1);
    World w;
    w.bodies = {mover, mover, mover, mover};
    Frame f;
    f.step(w, opts());
    w.bodies[1].vx = I(0);
    w.bodies[3].vx = I(0);
    for (int k = 0; k < 3; ++k) f.step(w, opts());
    CHECK(f.stats().step[ds::kStepVelocityX].processed == 4);
    f.step(w, opts());
    CHECK(f.stats().step[ds::kStepVelocityX].processed == 2);
    // One still of three is too few: every body is stepped in both
    // sub-frames, frame after frame.
    w.bodies = {mover, still, mover};
    FrameOptions two = opts();
    two.substeps = 2;
    Frame g;
    for (int k = 0; k < 4; ++k) g.step(w, two);
    CHECK(g.stats().step[ds::kStepVelocityX].processed == 6);
}

TEST_CASE("a body that stops being solid loses its supporter slot") {
    // Frame 1: both solid, the first holds slot 0. Frame 2: the first is no
    // longer solid and stands on the second, which now holds slot 0; a slot
    // left over from frame 1 would make the first skip it as "itself".
    World w;
    Body top = player(0, 0);
    Body floor = solid_box(0, 16, 16, 16);
    floor.immovable = true;
    w.bodies = {top, floor};
    Frame f;
    f.step(w, opts());
    w.bodies[0] = box(0, 0, 16, 16);
    w.bodies[0].gravity = true;
    f.step(w, opts());
    CHECK(w.bodies[0].on_ground);
    CHECK(f.stats().step[ds::kStepEntityCollisions].processed == 1);
}

TEST_CASE("steps report the bodies they did not visit as skipped") {
    World w;
    Body a = box(0, 0, 8, 8), g = box(20, 0, 8, 8);
    g.group = 7;
    w.bodies = {a, g, a};
    Frame f;
    f.step(w, opts());
    const auto& st = f.stats().step;
    CHECK(st[ds::kStepGroups].processed == 1);
    CHECK(st[ds::kStepGroups].skipped == 2);
    CHECK(st[ds::kStepEntityCollisions].processed == 0);
    CHECK(st[ds::kStepEntityCollisions].skipped == 3);
    CHECK(st[ds::kStepVelocityX].processed == 3);
}

}  // TEST_SUITE
