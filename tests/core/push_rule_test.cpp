// SPDX-License-Identifier: MIT
// Push-apart against the map (semantics §4, "push-apart never leaves a body
// in a solid"): the default push rule, against the seed's.
#include <algorithm>

#include "contacts.hpp"
#include "frame.hpp"
#include "support.hpp"

using namespace dst;
using ds::Frame;
using ds::FrameOptions;
using ds::PushRule;
using ds::World;

namespace {

FrameOptions under(PushRule rule) {
    FrameOptions o;
    o.push = rule;
    return o;
}

Body falling(double x, double y) {
    Body b = solid_box(x, y, 16, 16);
    b.gravity = true;
    return b;
}

// How far the deepest body reaches below `top` (0 when none does).
double deepest_below(const World& w, double top) {
    double d = 0;
    for (const Body& b : w.bodies) d = std::max(d, (b.y + b.h).v - top);
    return d;
}

}  // namespace

TEST_SUITE("push-rule") {

TEST_CASE("a column of boxes landing on a floor ends with none inside it") {
    // The floor is row 6, y ∈ [96, 112); five boxes overlap 4 px each.
    const auto g = grid({"....", "....", "....", "....", "....", "....", "####"});
    World w;
    w.grid = &g;
    for (int k = 0; k < 5; ++k) w.bodies.push_back(falling(16, 16 + 12 * k));
    Frame f;
    double worst = 0;
    for (int frame = 0; frame < 120; ++frame) {
        f.step(w, FrameOptions{});
        worst = std::max(worst, deepest_below(w, 96));
    }
    CHECK(worst == 0);
    CHECK_EXACT(w.bodies[4].y, 80);  // the lowest, on the floor

    // The seed's rule shoves the lowest box into the floor.
    World seed;
    seed.grid = &g;
    for (int k = 0; k < 5; ++k) seed.bodies.push_back(falling(16, 16 + 12 * k));
    Frame fs;
    double seed_worst = 0;
    for (int frame = 0; frame < 120; ++frame) {
        fs.step(seed, under(PushRule::Seed));
        seed_worst = std::max(seed_worst, deepest_below(seed, 96));
    }
    CHECK(seed_worst > 1);
}

TEST_CASE("a box pushed sideways into a wall stops flush, and the other takes the rest") {
    // The wall is column 3, x ∈ [48, 64).
    const auto g = grid({"...#", "...#", "...#"});
    Body a = solid_box(30, 8, 16, 16), b = solid_box(20, 8, 16, 16);  // 6 px deep
    CHECK(ds::resolve_pair(a, b, false, false, &g) == ds::kSideLeft);
    CHECK_EXACT(a.x, 32);  // its 3 px cut to 2, flush with the wall
    CHECK_EXACT(b.x, 16);  // its own 3 px and the 1 px a could not take
    Body sa = solid_box(30, 8, 16, 16), sb = solid_box(20, 8, 16, 16);
    ds::resolve_pair(sa, sb);  // the seed's rule
    CHECK_EXACT(sa.x, 33);
    CHECK_EXACT(sb.x, 17);

    SUBCASE("both blocked: what neither can take is dropped") {
        // Walls at columns 0 and 3: room for 32 px, two 17 px boxes.
        const auto narrow = grid({"#..#", "#..#"});
        Body l = solid_box(16, 8, 17, 8), r = solid_box(31, 8, 17, 8);
        ds::resolve_pair(l, r, false, false, &narrow);
        CHECK_EXACT(l.x, 16);
        CHECK_EXACT(r.x, 31);
    }
    SUBCASE("against an immovable body, the cut move is all") {
        Body m = solid_box(30, 8, 16, 16), wall = wall_box(20, 4, 16, 24);
        ds::resolve_pair(wall, m, false, false, &g);
        CHECK_EXACT(m.x, 32);  // to 36 the seed would go; the wall cuts it at 48
    }
}

TEST_CASE("a box spawned inside a floor is put on top of it") {
    // The floor is rows 6 and 7, y ∈ [96, 128): 4 px in, out by 20 up
    // (28 down; left and right, out of the grid: 32 and 48).
    const auto g = grid({"....", "....", "....", "....", "....", "....", "####", "####"});
    World w;
    w.grid = &g;
    w.bodies = {solid_box(16, 100, 16, 16)};  // no gravity: no tile step moves it
    Frame f;
    f.step(w, FrameOptions{});
    CHECK_EXACT(w.bodies[0].y, 80);
    CHECK_EXACT(w.bodies[0].x, 16);
    World seed;
    seed.grid = &g;
    seed.bodies = {solid_box(16, 100, 16, 16)};
    Frame fs;
    fs.step(seed, under(PushRule::Seed));
    CHECK_EXACT(seed.bodies[0].y, 100);  // the seed leaves it where it is
}

}  // TEST_SUITE
