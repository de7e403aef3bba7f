// SPDX-License-Identifier: MIT
// Carriers (carry.hpp, semantics §11): riders carried by a moving platform,
// bodies crushed against solid cells, on both whole-frame paths.
#include <vector>

#include "carry.hpp"
#include "frame.hpp"
#include "support.hpp"

using namespace dst;
using ds::Frame;
using ds::FrameOptions;
using ds::World;

namespace {

Body carrier(double x, double y, double vx, double vy) {
    Body b = wall_box(x, y, 64, 16);
    b.carries = true;
    b.vx = I(vx);
    b.vy = I(vy);
    return b;
}

Body rider(double x, double y) {  // standing on a carrier whose top is y + 16
    Body b = solid_box(x, y, 16, 16);
    b.gravity = true;
    return b;
}

// Still bodies that depend on nobody: they can settle, so a World keeps
// tracking sleep (at least half the bodies can); moving ones cannot.
void add_bystanders(World& w, int n, double vx) {
    for (int i = 0; i < n; ++i) {
        Body b = box(500 + 20 * i, 0, 8, 8);
        b.vx = I(vx);
        w.bodies.push_back(b);
    }
}

}  // namespace

TEST_SUITE("carry") {

TEST_CASE("a rider moves with its carrier, in the same frame, with and without sleep tracking") {
    for (const double bystander_vx : {0.0, 1.0}) {
        CAPTURE(bystander_vx);
        World w;
        w.bodies = {carrier(0, 100, 2, 0), rider(10, 84)};
        add_bystanders(w, 10, bystander_vx);
        Frame f;
        for (int k = 1; k <= 10; ++k) {
            f.step(w, FrameOptions{});
            CHECK_EXACT(w.bodies[1].x, 10 + 2 * k);
            CHECK_EXACT(w.bodies[1].y, 84);
            CHECK(w.bodies[1].on_ground);
            CHECK(!w.bodies[1].crushed);
        }
        // Still bystanders sleep (only the carrier and its rider are
        // stepped); moving ones keep every body awake.
        CHECK(f.stats().step[ds::kStepVelocityX].processed == (bystander_vx == 0 ? 2u : 12u));
    }
}

TEST_CASE("without #:carries? the rider is left behind") {
    World w;
    Body platform = carrier(0, 100, 2, 0);
    platform.carries = false;
    w.bodies = {platform, rider(10, 84)};
    Frame f;
    f.step(w, FrameOptions{});
    CHECK_EXACT(w.bodies[1].x, 10);
}

TEST_CASE("with sub-frames each carries its share") {
    World w;
    w.bodies = {carrier(0, 100, 2, 0), rider(10, 84)};
    FrameOptions opts;
    opts.substeps = 2;
    Frame f;
    f.step(w, opts);
    CHECK_FLONUM(w.bodies[1].x, 12.0);
}

TEST_CASE("a rider carried into a wall stops flush with it") {
    // Column 3, x ∈ [48, 64), rows 0–5: the platform (rows 6–7) passes under.
    const auto g = grid({"...#", "...#", "...#", "...#", "...#", "...#", "....", "....", "...."});
    World w;
    w.grid = &g;
    w.bodies = {carrier(0, 100, 6, 0), rider(20, 84)};
    Frame f;
    for (int k = 0; k < 3; ++k) f.step(w, FrameOptions{});
    CHECK_EXACT(w.bodies[1].x, 32);
    CHECK_EXACT(w.bodies[1].vx, 0);
    CHECK(!w.bodies[1].crushed);
}

TEST_CASE("a rider lifted into a ceiling is crushed, and uncrushed when it is not any more") {
    const auto g = grid({"....", "....", "....", "....", "####", "....", "....", "...."});
    World w;
    w.grid = &g;
    w.bodies = {carrier(0, 100, 0, -6), rider(10, 84)};  // the rider's vy 0 is not the carrier's
    Frame f;
    f.step(w, FrameOptions{});
    CHECK(w.bodies[1].crushed);
    // Push-apart's lift onto the carrier (to 78) is cut at the ceiling (§4).
    CHECK_EXACT(w.bodies[1].y, 80);
    w.bodies[0].vy = I(0);
    w.bodies[1].y = I(84);
    w.bodies[0].y = I(100);
    f.step(w, FrameOptions{});
    CHECK(!w.bodies[1].crushed);
}

TEST_CASE("a body a carrier pushes into a wall is crushed") {
    // The floor is row 6 (y ∈ [96, 112)), the wall column 3 (x ∈ [48, 64)).
    const auto g = grid({"...#", "...#", "...#", "...#", "...#", "...#", "####"});
    World w;
    w.grid = &g;
    Body platform = wall_box(0, 80, 20, 16);
    platform.carries = true;
    platform.vx = I(14);
    w.bodies = {platform, solid_box(30, 80, 16, 16)};
    Frame f;
    f.step(w, FrameOptions{});
    // The push clear of the platform (to 34) is cut at the wall (§4): it
    // stays flush with the wall, held in the platform, and is crushed.
    CHECK_EXACT(w.bodies[1].x, 32);
    CHECK(w.bodies[1].crushed);
    FrameOptions seed;
    seed.push = ds::PushRule::Seed;
    w.bodies = {platform, solid_box(30, 80, 16, 16)};
    Frame f2;
    f2.step(w, seed);
    CHECK_EXACT(w.bodies[1].x, 34);  // the seed's rule: pushed clear of the platform, into the wall
    CHECK(w.bodies[1].crushed);
}

TEST_CASE("a platform moving down by its velocity keeps its rider on it") {
    World w;
    w.bodies = {carrier(0, 100, 0, 6), rider(10, 84)};
    Frame f;
    for (int k = 1; k <= 10; ++k) {
        f.step(w, FrameOptions{});
        CHECK_EXACT(w.bodies[1].y, 84 + 6 * k);
        CHECK_EXACT(w.bodies[1].vy, 0);
    }
}

TEST_CASE("a body on two carriers rides only the first") {
    World w;
    w.bodies = {carrier(0, 100, 2, 0), rider(50, 84), carrier(60, 100, -3, 0)};
    Frame f;
    f.step(w, FrameOptions{});
    CHECK_EXACT(w.bodies[1].x, 52);
}

TEST_CASE("only solid, immovable, non-ghost bodies carry") {
    Body c = carrier(0, 0, 1, 0);
    CHECK(ds::is_carrier(c));
    c.skip = ds::kSkipEntityCollisions;
    CHECK(!ds::is_carrier(c));
    c = carrier(0, 0, 1, 0);
    c.immovable = false;
    CHECK(!ds::is_carrier(c));
    Body r = rider(0, 0);
    CHECK(ds::may_ride(r));
    r.skip = ds::kSkipCarry;
    CHECK(!ds::may_ride(r));
    CHECK(ds::is_crushable(r));
}

}  // TEST_SUITE
