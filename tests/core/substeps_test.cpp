// SPDX-License-Identifier: MIT
// The frame options beyond the seed: sub-frames (FrameOptions::substeps) and
// resting contacts (FrameOptions::resting_contacts).
#include <vector>

#include "frame.hpp"
#include "support.hpp"

using namespace dst;
using ds::Frame;
using ds::FrameOptions;
using ds::World;

namespace {

FrameOptions with(int substeps, bool resting = false) {
    FrameOptions o;
    o.substeps = substeps;
    o.resting_contacts = resting;
    return o;
}

Body faller() {
    Body b = box(0, 0, 8, 8);
    b.gravity = true;
    return b;
}

// n solid 8×8 gravity boxes standing on the floor of g (top at floor_y), touching.
std::vector<Body> stack(int n, double floor_y) {
    std::vector<Body> out;
    for (int i = 0; i < n; ++i) {
        Body b = solid_box(24, floor_y - 8 * (i + 1), 8, 8);
        b.gravity = true;
        b.on_ground = true;
        out.push_back(b);
    }
    return out;
}

}  // namespace

TEST_SUITE("substeps") {

TEST_CASE("sub-frames: from rest, y after t frames is t²/2 + t/(2k)") {
    for (int k : {1, 2, 4, 8}) {
        World w;
        w.bodies = {faller()};
        Frame f;
        for (int t = 1; t <= 10; ++t) {
            f.step(w, with(k));
            const double want = t * t / 2.0 + t / (2.0 * k);
            CHECK(w.bodies[0].y.v == want);  // every term is a dyadic fraction: exact
            CHECK(w.bodies[0].vy.v == t);
            CHECK(w.bodies[0].y.exact == (k == 1));
        }
    }
}

TEST_CASE("sub-frames: the one-shot acceleration goes in the first only") {
    World w;
    Body b = faller();
    b.ay = I(-15);
    w.bodies = {b};
    Frame f;
    f.step(w, with(4));
    CHECK(w.bodies[0].vy.v == -14.0);
    CHECK(w.bodies[0].y.v == -14.375);  // (−14.75 − 14.5 − 14.25 − 14) / 4
    CHECK_EXACT(w.bodies[0].ay, 0);
}

TEST_CASE("sub-frames: a still body keeps its exact coordinates") {
    World w;
    w.bodies = {box(100, 5, 8, 8)};
    Frame f;
    f.step(w, with(3));
    CHECK_EXACT(w.bodies[0].x, 100);
    CHECK_EXACT(w.bodies[0].y, 5);
}

TEST_CASE("sub-frames: swept tile tests cover each sub-frame's move") {
    const auto g = grid({"....#...", "....#...", "....#...", "....#..."});
    for (int k : {1, 2, 3, 8}) {
        World w;
        w.grid = &g;
        Body b = box(0, 16, 8, 8);
        b.vx = I(300);
        w.bodies = {b};
        Frame f;
        f.step(w, with(k));
        CHECK(w.bodies[0].x.v == 56);  // flush against column 4
        CHECK(w.bodies[0].vx.v == 0);
    }
}

TEST_CASE("resting contacts: a 20-box stack stays exactly where it is") {
    const auto g = grid({"....", "....", "....", "....", "####"});
    for (int k : {1, 4}) {
        World w;
        w.grid = &g;
        w.bodies = stack(20, 64);
        const std::vector<Body> start = w.bodies;
        Frame f;
        for (int t = 0; t < 1000; ++t) f.step(w, with(k, true));
        for (size_t i = 0; i < start.size(); ++i) CHECK(same_body(w.bodies[i], start[i]));
    }
}

TEST_CASE("resting contacts are off by default: the seed's stack moves") {
    const auto g = grid({"....", "....", "....", "....", "####"});
    World w;
    w.grid = &g;
    w.bodies = stack(20, 64);
    const std::vector<Body> start = w.bodies;
    Frame f;
    for (int t = 0; t < 50; ++t) f.step(w, FrameOptions{});
    bool moved = false;
    for (size_t i = 0; i < start.size(); ++i) moved |= !same_body(w.bodies[i], start[i]);
    CHECK(moved);
}

TEST_CASE("resting contacts: a box landing on a resting one stops on top") {
    const auto g = grid({"....", "....", "....", "....", "####"});
    World w;
    w.grid = &g;
    w.bodies = stack(1, 64);
    Body lander = solid_box(24, 46, 8, 8);
    lander.gravity = true;
    lander.vy = I(5);
    w.bodies.push_back(lander);
    Frame f;
    f.step(w, with(1, true));
    // vy 6 takes it to 52, 4 px into the resting box, which holds it up
    CHECK_EXACT(w.bodies[1].y, 48);
    CHECK_EXACT(w.bodies[1].vy, 0);
    CHECK_EXACT(w.bodies[0].y, 56);
    f.step(w, with(1, true));
    CHECK(w.bodies[1].on_ground);
    CHECK_EXACT(w.bodies[1].y, 48);
}

}  // TEST_SUITE
