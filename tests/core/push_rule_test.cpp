// SPDX-License-Identifier: MIT
// Push-apart against the map (semantics §4, "push-apart never leaves a body
// in a solid"): the default push rule, against the seed's.
#include <algorithm>
#include <chrono>
#include <vector>

#include "contacts.hpp"
#include "frame.hpp"
#include "support.hpp"
#include "detail/tile_clip.hpp"

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

// A 45° floor ramp as Tiled's collision editor gives it (16 px tiles):
// up to the right ('/') or up to the left ('\\').
ds::CellShape ramp45(bool up_right) {
    ds::CellShape s;
    s.x0 = 0, s.y0 = 0, s.x1 = 16, s.y1 = 16, s.cut = ds::Cut::Floor;
    s.ax = 0, s.ay = up_right ? 16 : 0, s.bx = 16, s.by = up_right ? 0 : 16;
    return s;
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

TEST_CASE("a push stops where the box meets a ramp's slope") {
    // '/' in cell (2, 1): x ∈ [32, 48), y ∈ [16, 32), its slant y = 64 − x.
    auto g = grid({"....", "....", "...."});
    g.set_shape(2, 1, ramp45(true));
    SUBCASE("sideways, the corner meets the slope") {
        // Feet at 28: the bottom right corner meets the slant at x = 36.
        const Body b = solid_box(20, 20, 8, 8);
        CHECK_EXACT(ds::clipped_push(b, true, I(12), g), 8);
        CHECK_EXACT(ds::clipped_push(b, true, I(7), g), 7);  // short of it: all
        // Already touching the slope: it cannot go up it at all.
        CHECK_EXACT(ds::clipped_push(solid_box(28, 20, 8, 8), true, I(5), g), 0);
        // Above the ramp's top nothing stops it.
        CHECK_EXACT(ds::clipped_push(solid_box(20, 4, 8, 8), true, I(30), g), 30);
    }
    SUBCASE("sideways into a ramp up to the left") {
        // '\\' in cell (1, 1): its slant y = x, met by the bottom left corner.
        auto h = grid({"....", "....", "...."});
        h.set_shape(1, 1, ramp45(false));
        CHECK_EXACT(ds::clipped_push(solid_box(40, 20, 8, 8), true, I(-20), h), -12);  // to x = 28
    }
    SUBCASE("down, the feet stop on the slope") {
        // Over [36, 44) the slope is highest at 44: y = 20.
        const Body b = solid_box(36, 0, 8, 8);
        CHECK_EXACT(ds::clipped_push(b, false, I(20), g), 12);
        CHECK_EXACT(ds::clipped_push(b, false, I(12), g), 12);  // exactly onto it
        CHECK_EXACT(ds::clipped_push(b, false, I(-3), g), -3);  // up: nothing above
    }
    SUBCASE("in a frame: a box landing on one that stands on the ramp") {
        // The lower box stands on the slope (feet at 20 over [36, 44)); the
        // upper lands 2 px deep. Clipped, the lower does not move at all:
        // the upper takes the whole 2 px.
        World w;
        w.grid = &g;
        w.bodies = {solid_box(36, 12, 8, 8), solid_box(36, 6, 8, 8)};
        ds::resolve_pair(w.bodies[0], w.bodies[1], false, false, &g);
        CHECK_EXACT(w.bodies[0].y, 12);
        CHECK_EXACT(w.bodies[1].y, 4);
    }
}

TEST_CASE("a box sunk into a ramp is put out by the shortest way") {
    auto g = grid({"....", "....", "...."});
    g.set_shape(2, 1, ramp45(true));
    // Over [40, 48) the slope's surface is 16; the feet are at 22: up 6,
    // left 16 (beside the shape's box), right 8, down 18 (under it).
    Body b = solid_box(40, 14, 8, 8);
    b.vy = I(3);
    CHECK(ds::put_out_of_solids(b, g));
    CHECK_EXACT(b.y, 8);
    CHECK_EXACT(b.x, 40);
    CHECK_EXACT(b.vy, 0);
    // Standing on the slope is not inside it.
    Body on = solid_box(40, 8, 8, 8);
    CHECK_FALSE(ds::put_out_of_solids(on, g));
}

TEST_CASE("put-out in enormous maps goes no further than the shortest way") {
    using Clock = std::chrono::steady_clock;
    SUBCASE("inside a 1 × 200 000 solid column: out sideways") {
        std::vector<uint8_t> cells(3 * 200000, 0);
        for (size_t r = 0; r < 200000; ++r) cells[r * 3 + 1] = ds::kSolidCell;
        const ds::TileGrid g(3, 200000, 16, 16, std::move(cells));
        Body b = solid_box(20, 1600004, 8, 8);  // up and down: 100 000 cells
        const auto t0 = Clock::now();
        CHECK(ds::put_out_of_solids(b, g));
        CHECK(Clock::now() - t0 < std::chrono::seconds(1));
        CHECK_EXACT(b.x, 8);  // left 12, a tie with right: left goes first
        CHECK_EXACT(b.y, 1600004);
    }
    SUBCASE("a 4000 × 4000 map filled solid: out of its nearest side") {
        const ds::TileGrid g(4000, 4000, 16, 16, std::vector<uint8_t>(size_t{4000} * 4000, ds::kSolidCell));
        // From x 32003, y 32005: up 32013, left 32011, right 31997, down 31995.
        Body b = solid_box(32003, 32005, 8, 8);
        const auto t0 = Clock::now();
        CHECK(ds::put_out_of_solids(b, g));
        CHECK(Clock::now() - t0 < std::chrono::seconds(1));
        CHECK_EXACT(b.x, 32003);
        CHECK_EXACT(b.y, 64000);
    }
}

}  // TEST_SUITE
