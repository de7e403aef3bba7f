// SPDX-License-Identifier: MIT
// Resting groups (settle.hpp): colliders at rest that push each other sleep
// as a group on the World path, and a run with them asleep equals, body for
// body and frame for frame, the same run with every body stepped.
#include <algorithm>
#include <cstring>
#include <vector>

#include "frame.hpp"
#include "support.hpp"

using namespace dst;
using ds::FrameOptions;
using ds::World;

namespace {

// 20 × 8 cells of 16 px, walled, the floor's top at y = 112.
ds::TileGrid arena() {
    return grid({"####################",
                 "#..................#",
                 "#..................#",
                 "#..................#",
                 "#..................#",
                 "#..................#",
                 "#..................#",
                 "####################"});
}

constexpr double kFloor = 112;

// A stack of eight 8×8 solid gravity boxes standing on the floor at x.
void stack(std::vector<Body>& bodies, double x) {
    for (int k = 0; k < 8; ++k) {
        Body b = solid_box(x, kFloor - 8 * (k + 1), 8, 8);
        b.gravity = true;
        bodies.push_back(b);
    }
}

FrameOptions resting() {
    FrameOptions o;
    o.resting_contacts = true;
    return o;
}

bool same_bits(const std::vector<Body>& a, const std::vector<Body>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Body)) == 0;
}

// The same scene stepped twice: `world` through Frame::step (which lets
// bodies sleep) and `plain` through Frame::step_physics with nobody asleep.
struct Twin {
    ds::TileGrid map = arena();
    World world;
    std::vector<Body> plain;
    ds::Frame sleeping, stepping;
    FrameOptions opts = resting();

    explicit Twin(std::vector<Body> bodies) {
        world.grid = &map;
        world.bodies = bodies;
        plain = std::move(bodies);
    }
    // One frame each; returns whether both left every body the same.
    bool step() {
        sleeping.step(world, opts);
        stepping.step_physics(plain, &map, opts);
        return same_bits(world.bodies, plain);
    }
    // Bodies the per-entity steps visited: velocity-x applies to every one
    // it visits (gravity does not count a body resting on another).
    uint64_t stepped() const { return sleeping.stats().step[ds::kStepVelocityX].processed; }

    uint64_t pushed() const { return sleeping.stats().step[ds::kStepEntityCollisions].processed; }
};

}  // namespace

TEST_SUITE("resting groups") {

TEST_CASE("a resting stack of eight is asleep from its third frame and costs no step") {
    std::vector<Body> bodies;
    stack(bodies, 32);
    Twin t(bodies);
    // Frame 1 steps the stack and leaves it as it was; frame 2, tracked,
    // finds it unchanged and forms the group; frame 3 on, it sleeps.
    for (int frame = 1; frame <= 2; ++frame) {
        REQUIRE(t.step());
        CHECK(t.stepped() == 8);
    }
    for (int frame = 3; frame <= 60; ++frame) {
        REQUIRE(t.step());
        CHECK(t.stepped() == 0);
        CHECK(t.pushed() == 0);
    }
    CHECK(t.world.bodies[7].y.v == kFloor - 64);
}

TEST_CASE("a box dropped on one of two stacks wakes only that stack, and the run equals stepping every body") {
    std::vector<Body> bodies;
    stack(bodies, 32);
    stack(bodies, 200);
    Body drop = solid_box(32, 0 + 16, 8, 8);  // falls from just under the ceiling onto the first stack
    drop.gravity = true;
    bodies.push_back(drop);
    Twin t(bodies);
    for (int frame = 1; frame <= 120; ++frame) {
        INFO("frame " << frame);
        REQUIRE(t.step());
        // Frames 1-2 step all 17; the stacks then sleep while the box falls
        // alone; from frame 6 its extent reaches the first stack, which
        // wakes (8 + 1), the far one staying asleep; from frame 10 the box
        // and its stack have rested a frame and sleep as one group.
        const uint64_t expected = frame <= 2 ? 17 : frame <= 5 ? 1 : frame <= 9 ? 9 : 0;
        CHECK(t.stepped() == expected);
    }
    CHECK(t.world.bodies[16].y.v == kFloor - 72);
}

TEST_CASE("with sub-frames, a group reached in a later one makes the frame run again, and the run equals stepping every body") {
    std::vector<Body> bodies;
    stack(bodies, 32);
    stack(bodies, 200);
    Body shot = solid_box(32, 16, 8, 8);  // 24 px over the first stack, held up by nothing, not falling
    bodies.push_back(shot);
    Twin t(bodies);
    t.opts.substeps = 4;
    for (int frame = 1; frame <= 60; ++frame) {
        INFO("frame " << frame);
        if (frame == 6) {  // thrown down by its owner: 6 px a sub-frame, reaching the stack in the fourth
            t.world.bodies[16].vy = I(24);
            t.plain[16].vy = I(24);
        }
        REQUIRE(t.step());
        // Counted per sub-frame: all 17 bodies, then none (three groups
        // asleep); from the throw the shot and the stack it lands on (the
        // frame run again once, the other stack asleep throughout), until
        // they have rested a frame.
        const uint64_t expected = frame <= 2 ? 4 * 17 : frame <= 5 ? 0 : frame <= 8 ? 4 * 9 : 0;
        CHECK(t.stepped() == expected);
    }
}

TEST_CASE("an edit to the map wakes every group") {
    std::vector<Body> bodies;
    stack(bodies, 32);
    stack(bodies, 200);
    Twin t(bodies);
    for (int frame = 1; frame <= 5; ++frame) REQUIRE(t.step());
    CHECK(t.stepped() == 0);
    t.map.set_solid(10, 1, true);  // far from both stacks
    REQUIRE(t.step());
    CHECK(t.stepped() == 16);
    REQUIRE(t.step());
    CHECK(t.stepped() == 16);  // unchanged once: grouped again
    REQUIRE(t.step());
    CHECK(t.stepped() == 0);
}

TEST_CASE("a body edited between frames wakes its own group only") {
    std::vector<Body> bodies;
    stack(bodies, 32);
    stack(bodies, 200);
    Twin t(bodies);
    for (int frame = 1; frame <= 5; ++frame) REQUIRE(t.step());
    CHECK(t.stepped() == 0);
    // The far stack's top box is nudged sideways by its owner.
    t.world.bodies[15].vx = I(1);
    t.plain[15].vx = I(1);
    REQUIRE(t.step());
    CHECK(t.stepped() == 8);
    for (int frame = 0; frame < 30; ++frame) REQUIRE(t.step());
}

TEST_CASE("a frame with a body that reports contacts lets no group sleep") {
    std::vector<Body> bodies;
    stack(bodies, 32);
    Body watcher = box(200, kFloor - 8, 8, 8);
    watcher.contacts = true;
    bodies.push_back(watcher);
    Twin t(bodies);
    for (int frame = 1; frame <= 10; ++frame) {
        REQUIRE(t.step());
        CHECK(t.stepped() >= 8);
    }
}

// A skips ground detection, so each frame gravity 10 sinks it 10 px into
// the immovable I and push-apart puts it back: it ends every frame as it
// began and sleeps, yet each frame its box reached 10 px under its feet.
// C rises under A's overhang, 6 px beside I: it must wake A while A's
// skipped frame would still have met it, not when C nears A's resting box.
TEST_CASE("a body that sinks into its support and is pushed back keeps the room it took on the way while asleep") {
    for (const int substeps : {1, 2}) {
        CAPTURE(substeps);
        std::vector<Body> bodies;
        Body c = solid_box(122, 70, 8, 8);
        c.vy = ds::Num::integer(-1);
        bodies.push_back(c);
        bodies.push_back(wall_box(100, 50, 16, 32));
        Body a = solid_box(84, 42, 48, 8);
        a.gravity = true;
        a.skip = ds::kSkipOnSolid;
        bodies.push_back(a);
        Twin t(bodies);
        t.opts = FrameOptions{};
        t.opts.gravity = ds::Num::integer(10);
        t.opts.substeps = substeps;
        std::vector<double> c_y;
        std::vector<uint64_t> stepped;
        for (int f = 0; f < 20; ++f) {
            CHECK(t.step());
            c_y.push_back(t.world.bodies[0].y.v);
            stepped.push_back(t.stepped());
        }
        CHECK(t.world.bodies[2].y.v == 42);
        if (substeps == 1) {
            // C rises until A's sunken box meets it, is pushed back down
            // and sinks on; A and I sleep while C is out of reach.
            CHECK(c_y == std::vector<double>{69, 68, 67, 66, 65, 64, 63, 62, 61, 60, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69});
            CHECK(stepped == std::vector<uint64_t>{3, 3, 1, 1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 1, 1});
        }
    }
}

TEST_CASE("stacks 1 px apart are groups of their own: a box dropped on one wakes only that one") {
    std::vector<Body> bodies;
    for (int k = 0; k < 4; ++k) stack(bodies, 32 + 9 * k);  // 1 px between neighbours, as the crowd bench
    Body drop = solid_box(32 + 9, 16, 8, 8);                // onto the second stack
    drop.gravity = true;
    bodies.push_back(drop);
    Twin t(bodies);
    std::vector<uint64_t> stepped;
    for (int frame = 1; frame <= 40; ++frame) {
        INFO("frame " << frame);
        REQUIRE(t.step());
        stepped.push_back(t.stepped());
    }
    // Frames 1-2 step all 33; then the falling box alone, then it and the
    // second stack (8 + 1), never the stacks beside it; then nothing.
    CHECK(std::vector<uint64_t>(stepped.begin(), stepped.begin() + 2) == std::vector<uint64_t>{33, 33});
    CHECK(*std::max_element(stepped.begin() + 2, stepped.end()) == 9);
    CHECK(stepped.back() == 0);
    CHECK(t.world.bodies[32].y.v == kFloor - 72);
}

// D slides into C, and their push carries C 1 px into the asleep stack S
// beside it: only the pass brings C within reach of S, which must then be
// stepped too (the frame runs again with S awake), as pairs after (C, D)
// in list order meet S.
TEST_CASE("a push that carries a body into an asleep group's room makes the frame run again with it awake") {
    std::vector<Body> bodies;
    Body c = solid_box(110, kFloor - 8, 8, 8);
    c.gravity = true;
    bodies.push_back(c);
    Body d = solid_box(160, kFloor - 8, 8, 8);
    d.gravity = true;
    d.vx = ds::Num::integer(-8);
    bodies.push_back(d);
    stack(bodies, 100);
    Twin t(bodies);
    std::vector<uint64_t> stepped;
    for (int frame = 1; frame <= 12; ++frame) {
        INFO("frame " << frame);
        REQUIRE(t.step());
        stepped.push_back(t.stepped());
    }
    // S (8) and C sleep from frame 3 while D slides alone; at frame 6 D
    // reaches C, which wakes on the spot, and the pass carries C into S's
    // room: the frame runs again with all 10 awake.
    CHECK(std::vector<uint64_t>(stepped.begin(), stepped.begin() + 6) == std::vector<uint64_t>{10, 10, 1, 1, 1, 10});
    CHECK(t.plain[0].x.v < 108);  // C ended inside S's column: it met S
}

}
