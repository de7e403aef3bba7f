// SPDX-License-Identifier: MIT
// Shaped cells (semantics §12): ramps and part-tile boxes, walked on,
// landed on, bumped into; every figure worked out by hand from the rule.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "frame.hpp"
#include "query.hpp"
#include "ground.hpp"
#include "support.hpp"
#include "tiles.hpp"
#include "detail/placed_shape.hpp"
#include "detail/tile_clip.hpp"

using namespace dst;
using ds::CellShape;
using ds::Cut;

namespace {

// 16 px ramps as Tiled's collision editor gives them (tile px, y down).
CellShape ramp(int x0, int y0, int x1, int y1, Cut cut, int ax, int ay, int bx, int by, bool one_way = false) {
    CellShape s;
    s.x0 = x0, s.y0 = y0, s.x1 = x1, s.y1 = y1, s.cut = cut;
    s.ax = ax, s.ay = ay, s.bx = bx, s.by = by, s.one_way = one_way;
    return s;
}
CellShape part_box(int x0, int y0, int x1, int y1) { return ramp(x0, y0, x1, y1, Cut::None, 0, 0, 0, 0); }

// A pentagon: 8 px walls under a 45° roof peaking at (8, 0); or, upside
// down, an underside with its lowest point at (8, 16).
CellShape house(bool upside_down) {
    CellShape s = upside_down ? ramp(0, 0, 16, 16, Cut::Ceiling, 0, 8, 8, 16) : ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, 0);
    s.n_more = 1;
    s.more[0] = upside_down ? ds::Slant{8, 16, 16, 8} : ds::Slant{8, 0, 16, 8};
    return s;
}

// A diamond: its top peaking at (8, 0), its underside lowest at (8, 16),
// its sides meeting at (0, 8) and (16, 8).
CellShape diamond() {
    CellShape s = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, 0);
    s.n_more = 1, s.more[0] = {8, 0, 16, 8};
    s.n_under = 2, s.under[0] = {0, 8, 8, 16}, s.under[1] = {8, 16, 16, 8};
    return s;
}

// '/' 45° up to the right, '\' 45° up to the left; 'a' 'b' the lower and
// upper tiles of a 1:2 ramp up to the right, 'd' 'c' the same up to the
// left; 'v' a 45° ceiling ramp (the '/' tile flipped vertically), '^' its
// mirror; '_' a half-height box at the bottom, '-' a 4 px ledge at the top;
// 'o' a one-way '/'; 'p' a house, 'u' one upside down; 'x' a diamond.
CellShape shape_of(char ch) {
    switch (ch) {
        case '/': return ramp(0, 0, 16, 16, Cut::Floor, 0, 16, 16, 0);
        case '\\': return ramp(0, 0, 16, 16, Cut::Floor, 0, 0, 16, 16);
        case 'a': return ramp(0, 8, 16, 16, Cut::Floor, 0, 16, 16, 8);
        case 'b': return ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 16, 0);
        case 'c': return ramp(0, 0, 16, 16, Cut::Floor, 0, 0, 16, 8);
        case 'd': return ramp(0, 8, 16, 16, Cut::Floor, 0, 8, 16, 16);
        case 'v': return ramp(0, 0, 16, 16, Cut::Ceiling, 0, 0, 16, 16);
        case '^': return ramp(0, 0, 16, 16, Cut::Ceiling, 0, 16, 16, 0);
        case '_': return part_box(0, 8, 16, 16);
        case '-': return part_box(0, 0, 16, 4);
        case 'o': return ramp(0, 0, 16, 16, Cut::Floor, 0, 16, 16, 0, true);
        case 'p': return house(false);
        case 'u': return house(true);
        case 'x': return diamond();
        default: FAIL("no shape for " << ch); return {};
    }
}

ds::TileGrid shaped_grid(const std::vector<std::string>& rows) {
    std::vector<std::string> whole;
    for (const auto& r : rows) {
        std::string w = r;
        for (char& c : w) c = c == '#' ? '#' : '.';
        whole.push_back(w);
    }
    ds::TileGrid g = grid(whole);
    for (size_t r = 0; r < rows.size(); ++r)
        for (size_t c = 0; c < rows[r].size(); ++c)
            if (rows[r][c] != '#' && rows[r][c] != '.')
                g.set_shape(static_cast<int64_t>(c), static_cast<int64_t>(r), shape_of(rows[r][c]));
    return g;
}

// One default frame for one body walking at a steady vx.
struct Walker {
    ds::TileGrid g;
    ds::World world;
    ds::Frame frame;
    Walker(const std::vector<std::string>& rows, Body b) : g(shaped_grid(rows)) {
        world.bodies = {b};
        world.grid = &g;
    }
    Body& body() { return world.bodies[0]; }
    void step(double vx) {
        body().vx = I(vx);
        frame.step(world, ds::FrameOptions{});
    }
};

Body walker(double x, double y) {
    Body b = box(x, y, 8, 16);
    b.gravity = true;
    b.on_ground = true;
    return b;
}

// A hill of 45° ramps: up from the floor (top 80) at x = 80 to the flat top
// (32) over x 128–176, down to the floor again at x = 224.
const std::vector<std::string> kHill45 = {
    "..................",
    "..................",
    "......./###\\......",
    "....../#####\\.....",
    "...../#######\\....",
    "##################",
};

// The hill's surface at x (the limit from the left at a corner).
double hill45(double x) {
    if (x < 80 || x > 224) return 80;
    if (x < 128) return 160 - x;
    if (x <= 176) return 32;
    return x - 144;
}
// Where a box over [x, x + 8) stands: the highest point under its bottom edge.
double hill45_feet(double x) {
    double feet = std::min(hill45(x), hill45(x + 8));
    if (x < 176 && x + 8 > 128) feet = 32;
    return feet;
}

}  // namespace

TEST_SUITE("slopes") {

TEST_CASE("a position a shape rule writes is exact only when exact in and an integer out") {
    using ds::shape_math::exact_if;
    CHECK(exact_if(true, 16.0).exact);
    CHECK(exact_if(true, -3.0).exact);
    CHECK(exact_if(true, -0.0).exact);
    CHECK_FALSE(exact_if(true, 16.5).exact);
    CHECK_FALSE(exact_if(true, -0.5).exact);
    CHECK_FALSE(exact_if(false, 16.0).exact);
    CHECK(exact_if(true, 0x1p52 - 1).exact);
    CHECK_FALSE(exact_if(true, 0x1p52 - 0.5).exact);
    CHECK(exact_if(true, 0x1p52).exact);  // every double from 2^52 on is an integer
    CHECK(exact_if(true, -1e300).exact);
    CHECK_FALSE(exact_if(true, std::nan("")).exact);
}

TEST_CASE("a 1:3 ramp on 12 px tiles (a run that is no power of two) is walked exactly") {
    // Three 12 px tiles rise 4 px each, from the floor (top 24) at x = 24 to
    // the flat top (12) at x = 60: the slant's heights are thirds, exact
    // every third pixel, where a 6 px box walking at vx 3 always has its
    // leading edge.
    const auto ramp13 = [](int y_low, int y_high) {
        return ramp(0, std::min(y_high, 12), 12, 12, Cut::Floor, 0, y_low, 12, y_high);
    };
    ds::TileGrid g = grid({"........", ".....###", "########"}, 12, 12);
    g.set_shape(2, 1, ramp13(12, 8));
    g.set_shape(3, 1, ramp13(8, 4));
    g.set_shape(4, 1, ramp13(4, 0));
    ds::World world;
    Body b = box(12, 12, 6, 12);
    b.gravity = b.on_ground = true;
    world.bodies = {b};
    world.grid = &g;
    ds::Frame frame;
    for (int f = 0; f < 20; ++f) {
        world.bodies[0].vx = I(3);
        frame.step(world, ds::FrameOptions{});
        const Body& w = world.bodies[0];
        const double lead = w.x.v + 6;
        const double feet = lead <= 24 ? 24 : lead <= 60 ? 24 - (lead - 24) / 3 : 12;
        CHECK_EXACT(w.x, 15 + 3 * f);
        CHECK_EXACT(w.y, feet - 12);
        CHECK(w.on_ground);
    }
}

TEST_CASE("walking up a 45° ramp moves y by exactly vx each frame and stays on the ground") {
    Walker w(kHill45, walker(60, 64));  // feet on the floor at y = 80
    for (int f = 0; f < 40; ++f) {
        const double x_before = w.body().x.v, y_before = w.body().y.v;
        w.step(2);
        CHECK_EXACT(w.body().x, x_before + 2);
        CHECK_EXACT(w.body().y, hill45_feet(w.body().x.v) - 16);
        CHECK(w.body().y.v >= y_before - 2);  // never more than vx per frame
        CHECK(w.body().on_ground);
    }
    CHECK_EXACT(w.body().y, 16);  // on the flat top
}

TEST_CASE("over the crest and down the other side: on the ground every frame, never stalls") {
    Walker w(kHill45, walker(60, 64));
    for (int f = 0; f < 70; ++f) {
        const double x_before = w.body().x.v;
        w.step(3);
        CHECK_EXACT(w.body().x, x_before + 3);
        CHECK_EXACT(w.body().y, hill45_feet(w.body().x.v) - 16);
        CHECK(w.body().on_ground);
    }
    CHECK_EXACT(w.body().x, 270);
    CHECK_EXACT(w.body().y, 64);
}

TEST_CASE("walking left up and down the same hill mirrors it") {
    Walker w(kHill45, walker(262, 64));
    for (int f = 0; f < 70; ++f) {
        const double x_before = w.body().x.v;
        w.step(-3);
        CHECK_EXACT(w.body().x, x_before - 3);
        CHECK_EXACT(w.body().y, hill45_feet(w.body().x.v) - 16);
        CHECK(w.body().on_ground);
    }
    CHECK_EXACT(w.body().x, 52);
}

// A 1:2 ramp over two tiles: from the floor (64) at x = 64 up to 48 at x = 96.
const std::vector<std::string> kRamp12 = {
    "............",
    "............",
    "............",
    "....ab######",
    "############",
};
double ramp12_feet(double x) { return std::clamp(64 - (x + 8 - 64) / 2, 48.0, 64.0); }

TEST_CASE("a 1:2 ramp moves y by vx/2: exact with an even vx") {
    Walker w(kRamp12, walker(40, 48));
    for (int f = 0; f < 40; ++f) {
        w.step(2);
        CHECK_EXACT(w.body().y, ramp12_feet(w.body().x.v) - 16);
        CHECK(w.body().on_ground);
    }
    CHECK_EXACT(w.body().x, 120);
    CHECK_EXACT(w.body().y, 32);
}

TEST_CASE("a 1:2 ramp with an odd vx stands at half pixels, as flonums from the first") {
    Walker w(kRamp12, walker(40, 48));
    bool halves = false;
    for (int f = 0; f < 30; ++f) {
        w.step(3);
        CHECK(w.body().y.v == ramp12_feet(w.body().x.v) - 16);
        if (w.body().y.v != std::floor(w.body().y.v)) halves = true;
        if (halves) CHECK_FALSE(w.body().y.exact);
        CHECK(w.body().on_ground);
    }
    CHECK(halves);
    CHECK_FLONUM(w.body().y, 32);  // on the flat top, still a flonum
}

TEST_CASE("walking down a 1:2 ramp to the left: on the ground every frame") {
    Walker w(kRamp12, walker(110, 32));
    for (int f = 0; f < 30; ++f) {
        w.step(-2);
        CHECK_EXACT(w.body().y, ramp12_feet(w.body().x.v) - 16);
        CHECK(w.body().on_ground);
    }
    CHECK_EXACT(w.body().y, 48);
}

TEST_CASE("two ramps joined: 45° then 1:2 then flat, no bump at either join") {
    // 45° from (32, 80) to (48, 64), then 1:2 from (48, 64) to (80, 48), then flat 48.
    Walker w({"........",
              "........",
              "........",
              "...ab###",
              "../#####",
              "########"},
             walker(8, 64));
    auto surface = [](double x) {
        if (x <= 32) return 80.0;
        if (x <= 48) return 80 - (x - 32);
        if (x <= 80) return 64 - (x - 48) / 2;
        return 48.0;
    };
    for (int f = 0; f < 40; ++f) {
        w.step(2);
        const double x = w.body().x.v;
        CHECK_EXACT(w.body().y, surface(x + 8) - 16);
        CHECK(w.body().on_ground);
    }
}

TEST_CASE("a body falling onto a ramp at any speed lands on its surface, swept") {
    for (double vy : {1.0, 7.0, 16.0, 33.0, 100.0, 500.0}) {
        for (double x : {84.0, 90.0, 100.0, 200.0}) {
            ds::TileGrid g = shaped_grid(kHill45);
            Body b = box(x, -600, 8, 16);
            b.gravity = true;
            b.vy = I(vy);
            for (int f = 0; f < 700 && !b.on_ground; ++f) {
                ds::World world;
                world.bodies = {b};
                world.grid = &g;
                ds::Frame frame;
                frame.step(world, ds::FrameOptions{});
                b = world.bodies[0];
                if (b.vy.v > vy) b.vy = I(vy);  // a steady fall
            }
            CAPTURE(vy);
            CAPTURE(x);
            CHECK(b.on_ground);
            CHECK_EXACT(b.y, hill45_feet(x) - 16);
        }
    }
}

TEST_CASE("a jump into a ceiling ramp stops with the head on its underside") {
    // 'v' at (2, 1): its underside y = 16 + (x − 32) over x 32–48.
    ds::TileGrid g = shaped_grid({"....", "..v.", "....", "####"});
    Body b = box(36, 40, 8, 8);  // head at 40, over x 36–44: lowest underside at x 44 → 28
    b.vy = I(-20);
    b.y = I(20);  // after the move
    CHECK(ds::resolve_tile_collisions_y(b, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(b.y, 28);
    CHECK_EXACT(b.vy, 0);
}

TEST_CASE("a body moving sideways into a ramp below its slant is stopped as by a wall") {
    // '/' at (2, 1) over x 32–48, y 16–32; the body's feet below its base.
    ds::TileGrid g = shaped_grid({"....", "../.", "....", "####"});
    Body b = box(26, 20, 8, 16);  // after moving right by 4: spans y 20–36
    b.vx = I(4);
    CHECK(ds::resolve_tile_collisions_x(b, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(b.x, 24);
    CHECK_EXACT(b.y, 20);
    CHECK_EXACT(b.vx, 0);
}

TEST_CASE("the tall side of a ramp is a wall, its slant is not") {
    ds::TileGrid g = shaped_grid({"....", "../.", "####"});
    // Moving left into the '/' tile's right side (x 48), feet on the floor (32).
    Body b = box(46, 16, 8, 16);
    b.vx = I(-4);
    CHECK(ds::resolve_tile_collisions_x(b, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(b.x, 48);
    // Moving right into its slant from the floor: lifted onto it.
    Body c = box(28, 16, 8, 16);  // corner at 36: top 32 − (36 − 32) = 28
    c.vx = I(4);
    ds::resolve_tile_collisions_x(c, &g, ds::CollisionMode::Swept);
    CHECK_EXACT(c.x, 28);
    CHECK_EXACT(c.y, 12);
    CHECK_EXACT(c.vx, 4);
}

TEST_CASE("part-tile boxes: a half-height tile is a low wall and a floor, a ledge is a ceiling") {
    ds::TileGrid g = shaped_grid({"....", "....", "..-.", "..__", "####"});
    // Walking right into the half-height box (x 32, top 56): a wall.
    Body w = box(26, 48, 8, 16);
    w.vx = I(4);
    CHECK(ds::resolve_tile_collisions_x(w, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(w.x, 24);
    // Falling onto it lands at its top, 56.
    Body f = box(36, 50, 8, 16);
    f.vy = I(10);
    CHECK(ds::resolve_tile_collisions_y(f, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(f.y, 40);
    f.gravity = true;
    CHECK(ds::tile_supports(f, g));
    // Jumping into the 4 px ledge above (y 32–36) from below: head at 36.
    Body j = box(36, 30, 8, 8);
    j.vy = I(-8);
    CHECK(ds::resolve_tile_collisions_y(j, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(j.y, 36);
}

TEST_CASE("a one-way ramp is walked up, and jumped through from below") {
    Walker w({"........", "........", "..o#####", "########"}, walker(0, 32));
    // Grid: 'o' at (2, 2) from (32, 48) up to (48, 32); '#' row 2 from x 48 is whole solid.
    for (int f = 0; f < 10; ++f) w.step(2);
    CHECK_EXACT(w.body().x, 20);
    CHECK_EXACT(w.body().y, 32 - 16 + 16 - std::min(16.0, std::max(0.0, 20 + 8 - 32.0)));
    CHECK(w.body().on_ground);
    // A body rising through it from below is not stopped.
    ds::TileGrid g = shaped_grid({"........", "........", "..o.....", "........"});
    Body j = box(36, 30, 8, 8);
    j.vy = I(-12);
    ds::resolve_tile_collisions_y(j, &g, ds::CollisionMode::Swept);
    CHECK_EXACT(j.y, 30);
    CHECK_EXACT(j.vy, -12);
}

TEST_CASE("a body walking off a ramp's top over a cliff falls, it is not snapped down") {
    Walker w({"..........", "..........", "...../....", "..../#....", "##########"}, walker(40, 48));
    // Up the ramp (x 64–96, top 32 at x 96), then over its edge: the floor
    // (64) is 32 px below, beyond |vx| × 1, so the body falls from there.
    for (int f = 0; f < 30; ++f) w.step(2);
    CHECK_EXACT(w.body().x, 100);
    CHECK_FALSE(w.body().on_ground);
}

TEST_CASE("standing on a ramp: blocked down, on the ground; a jump from it leaves it") {
    Walker w(kHill45, walker(90, 40));  // over the up-ramp; let it settle
    w.body().contacts = true;
    for (int f = 0; f < 30; ++f) w.step(0);
    // Over x 90–98 the ramp's highest point is at x 98: y = 160 − 98 = 62.
    CHECK_EXACT(w.body().y, 62 - 16);
    CHECK(w.body().on_ground);
    CHECK(w.body().blocked == ds::kSideDown);
    // The jump: vy −15 + 1 on its first frame, rising off the ramp.
    w.body().ay = I(-15);
    w.step(0);
    CHECK_EXACT(w.body().vy, -14);
    CHECK_EXACT(w.body().y, 46 - 14);
    CHECK_FALSE(w.body().on_ground);
    CHECK(w.body().blocked == 0);
}

std::vector<ds::RayHit> ray(const ds::TileGrid& g, double x0, double y0, double x1, double y1) {
    std::vector<ds::RayHit> hits;
    ds::raycast_cells(g, ds::Segment{x0, y0, x1, y1}, false, hits);
    return hits;
}

TEST_CASE("rays hit a ramp's slant, its sides and part-tile boxes as drawn") {
    // '/' at (2, 1): x 32–48, y 16–32.
    const ds::TileGrid g = shaped_grid({"....", "../.", "...."});
    // In the world the slant runs from (32, 32) to (48, 16): y = 64 − x.
    auto down = ray(g, 40, 0, 40, 64);
    REQUIRE(down.size() == 1);
    CHECK(down[0].y == 24);
    CHECK(down[0].t == 24.0 / 64);
    CHECK(down[0].nx == -1);
    CHECK(down[0].ny == -1);
    CHECK(down[0].col == 2);
    // From the left at y = 28: the slant is at x = 64 − 28 = 36.
    auto right = ray(g, 0, 28, 64, 28);
    REQUIRE(right.size() == 1);
    CHECK(right[0].x == 36);
    // From the right at y = 20: the tall side x = 48.
    auto left = ray(g, 63, 20, 0, 20);
    REQUIRE(left.size() == 1);
    CHECK(left[0].x == 48);
    CHECK(left[0].nx == 1);
    CHECK(left[0].ny == 0);
    // From below at x = 40: the flat bottom y = 32.
    auto up = ray(g, 40, 47, 40, 0);
    REQUIRE(up.size() == 1);
    CHECK(up[0].y == 32);
    CHECK(up[0].ny == 1);
    // Over the empty part of the cell, above the slant: no hit.
    CHECK(ray(g, 33, 16, 33, 30).empty());
    // Starting above the slant inside the ramp's cell: it hits within the cell.
    auto inside = ray(g, 44, 17, 44, 40);
    REQUIRE(inside.size() == 1);
    CHECK(inside[0].y == 20);
    // Starting inside the solid: not hit.
    CHECK(ray(g, 46, 30, 46, 47).empty());
}

TEST_CASE("rays: ceiling ramps, part-tile boxes, one-way shapes") {
    const ds::TileGrid g = shaped_grid({"....", ".v_o", "...."});
    // 'v' at (1, 1): a ceiling ramp, solid above y = x from (16, 16) to (32, 32).
    auto up = ray(g, 28, 47, 28, 0);
    REQUIRE(up.size() == 1);
    CHECK(up[0].y == 28);
    CHECK(up[0].nx == -1);  // the slant faces down and to the left
    CHECK(up[0].ny == 1);
    // '_' at (2, 1): the bottom half, y 24–32.
    auto down = ray(g, 40, 0, 40, 47);
    REQUIRE(down.size() == 1);
    CHECK(down[0].y == 24);
    CHECK(down[0].ny == -1);
    // 'o' at (3, 1) is one-way: rays pass.
    CHECK(ray(g, 56, 0, 56, 47).empty());
}

// ---- convex polygons: a house's roof and an upside-down house's underside.
// 'p' at (2, 1): x 32–48, y 16–32, walls up to y 24, roof y = 56 − x up to
// the peak (40, 16), then y = x − 24. 'u' at (2, 1): underside y = x − 8 down
// to (40, 32), then y = 72 − x.

TEST_CASE("landing on a roof: on its peak, and on either slope at the point of the span nearest the peak") {
    const ds::TileGrid g = shaped_grid({"....", "..p.", "####"});
    auto land = [&](double x) {
        Body b = box(x, 16, 8, 8);  // fell 20 px from feet at 4
        b.vy = I(20);
        CHECK(ds::resolve_tile_collisions_y(b, &g, ds::CollisionMode::Swept));
        CHECK_EXACT(b.vy, 0);
        return b.y;
    };
    CHECK_EXACT(land(36), 8);   // over 36–44: the peak, 16
    CHECK_EXACT(land(30), 10);  // over 32–38: the left slope at 38, 18
    CHECK_EXACT(land(42), 10);  // over 42–48: the right slope at 42, 18
    CHECK_EXACT(land(45), 13);  // over 45–48: 21
}

TEST_CASE("a roof's wall stops a body beside it; its slope lifts one above the wall's top") {
    const ds::TileGrid g = shaped_grid({"....", "..p.", "####"});
    Body wall = box(26, 16, 8, 16);  // moved right 4, feet on the floor at 32
    wall.vx = I(4);
    CHECK(ds::resolve_tile_collisions_x(wall, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(wall.x, 24);
    CHECK_EXACT(wall.vx, 0);
    Body up = box(28, 8, 8, 16);  // feet at 24, the wall's top; lead now at 36: roof 20
    up.vx = I(4);
    ds::resolve_tile_collisions_x(up, &g, ds::CollisionMode::Swept);
    CHECK_EXACT(up.x, 28);
    CHECK_EXACT(up.vx, 4);
    CHECK_EXACT(up.y, 4);
    // Pushed (§4) with feet at 17, a px below the peak: the corner meets the
    // roof at x = 39.
    CHECK_EXACT(ds::clipped_push(box(20, 1, 8, 16), true, I(12), g), 11);
    CHECK_EXACT(ds::clipped_push(box(20, -1, 8, 16), true, I(30), g), 30);   // over the peak
    CHECK_EXACT(ds::clipped_push(box(60, 1, 8, 16), true, I(-30), g), -19);  // from the right: to x = 41
}

TEST_CASE("walking over a roof between two half-height boxes: on the ground every frame") {
    // '_' at x 32–48 and 64–80 (top 24), 'p' at x 48–64: roof 72 − x to
    // the peak (56, 16), then x − 40.
    Walker w({"......", ".._p_.", "######"}, walker(30, 8));
    auto ground = [](double x) {
        if (x < 48 || x >= 64) return 24.0;
        return std::max(72 - x, x - 40);
    };
    for (int f = 0; f < 22; ++f) {
        w.step(2);
        const double x = w.body().x.v;
        CAPTURE(x);
        CHECK_EXACT(w.body().x, 32 + 2 * f);
        CHECK_EXACT(w.body().y, ground(std::clamp(56.0, x, x + 8)) - 16);
        CHECK(w.body().on_ground);
    }
    CHECK_EXACT(w.body().y, 8);
}

// A ceiling shape's underside and a diamond's (two-sided) are the same
// lines here: a head meets both alike.
TEST_CASE("a jump into an underside, a ceiling's or a diamond's, stops the head on its lowest point over the span") {
    for (const char* row : {"..u.", "..x."}) {
        CAPTURE(row);
        const ds::TileGrid g = shaped_grid({"....", row, "...."});
        auto bump = [&](double x) {
            Body b = box(x, 20, 8, 8);  // rose 20 px from its head at 40
            b.vy = I(-20);
            CHECK(ds::resolve_tile_collisions_y(b, &g, ds::CollisionMode::Swept));
            return b.y;
        };
        CHECK_EXACT(bump(36), 32);  // over 36–44: the lowest point, (40, 32)
        CHECK_EXACT(bump(42), 30);  // over 42–48: 72 − 42
        CHECK_EXACT(bump(28), 28);  // over 32–36: 36 − 8
    }
}

TEST_CASE("rays hit a roof's slopes with their normals") {
    const ds::TileGrid g = shaped_grid({"....", "..p.", "...."});
    auto left = ray(g, 36, 0, 36, 64);
    REQUIRE(left.size() == 1);
    CHECK(left[0].y == 20);
    CHECK(left[0].nx == -1);
    CHECK(left[0].ny == -1);
    auto right = ray(g, 44, 0, 44, 64);
    REQUIRE(right.size() == 1);
    CHECK(right[0].y == 20);
    CHECK(right[0].nx == 1);
    CHECK(right[0].ny == -1);
    CHECK(ray(g, 33, 16, 33, 22).empty());  // above the roof, inside the cell
    CHECK(g.solid_at(40, 16));
    CHECK_FALSE(g.solid_at(35, 20));
}

// ---- a diamond, slanted on its top and its underside. 'x' at (2, 1): x
// 32–48, y 16–32, top y = 56 − x up to (40, 16), then x − 24; underside
// y = x − 8 down to (40, 32), then 72 − x; its sides meet at (32, 24) and
// (48, 24).

TEST_CASE("landing on a diamond: on its top vertex, and on either slope nearest it") {
    const ds::TileGrid g = shaped_grid({"....", "..x.", "...."});
    auto land = [&](double x) {
        Body b = box(x, 16, 8, 8);  // fell 20 px from feet at 4
        b.vy = I(20);
        CHECK(ds::resolve_tile_collisions_y(b, &g, ds::CollisionMode::Swept));
        CHECK_EXACT(b.vy, 0);
        return b.y;
    };
    CHECK_EXACT(land(36), 8);   // over 36–44: the vertex, 16
    CHECK_EXACT(land(30), 10);  // over 32–38: the left slope at 38, 18
    CHECK_EXACT(land(42), 10);  // over 42–48: the right slope at 42, 18
    CHECK_EXACT(land(45), 13);  // over 45–48: 21
    Body past = box(20, 16, 8, 8);  // beside it: falls on
    past.vy = I(20);
    ds::resolve_tile_collisions_y(past, &g, ds::CollisionMode::Swept);
    CHECK_EXACT(past.y, 16);
    CHECK_EXACT(past.vy, 20);
}

TEST_CASE("a diamond's side vertex stops a body spanning it; a corner stops on the slope it meets") {
    const ds::TileGrid g = shaped_grid({"....", "..x.", "...."});
    Body wall = box(26, 16, 8, 16);  // moved right 4 to lead 34, spanning y 24
    wall.vx = I(4);
    CHECK(ds::resolve_tile_collisions_x(wall, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(wall.x, 24);
    CHECK_EXACT(wall.vx, 0);
    Body back = box(46, 16, 8, 16);  // moved left 4 onto the right vertex
    back.vx = I(-4);
    CHECK(ds::resolve_tile_collisions_x(back, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(back.x, 48);
    // Pushed (§4): feet at 20 meet the top's left slope at x = 36; a head
    // at 26 the underside's at x = 34; from the right, a head at 26 meets
    // 72 − x at x = 46.
    CHECK_EXACT(ds::clipped_push(box(20, 4, 8, 16), true, I(12), g), 8);
    CHECK_EXACT(ds::clipped_push(box(20, 26, 8, 8), true, I(12), g), 6);
    CHECK_EXACT(ds::clipped_push(box(60, 26, 8, 8), true, I(-30), g), -14);
    CHECK_EXACT(ds::clipped_push(box(20, 8, 8, 8), true, I(30), g), 30);   // over the top vertex
    CHECK_EXACT(ds::clipped_push(box(20, 31, 8, 8), true, I(30), g), 11);  // a head at 31: x = 39
    CHECK_EXACT(ds::clipped_push(box(20, 22, 8, 4), true, I(12), g), 4);   // spanning the vertex: its side
}

TEST_CASE("a diamond's lower slope lifts a walker onto its top, as a roof's slope does") {
    // 'x' standing on the floor at y 32: a walker 8 px tall, feet at 32,
    // moved right to lead 36, overlaps its underside over 32–36 (lowest
    // 28) and is lifted onto its top there, 56 − 36 = 20.
    const ds::TileGrid g = shaped_grid({"....", "..x.", "####"});
    Body b = box(28, 24, 8, 8);
    b.vx = I(4);
    ds::resolve_tile_collisions_x(b, &g, ds::CollisionMode::Swept);
    CHECK_EXACT(b.vx, 4);
    CHECK_EXACT(b.x, 28);
    CHECK_EXACT(b.y, 12);
}

TEST_CASE("rays hit a diamond's top and underside with their normals; solid_at is its inside") {
    const ds::TileGrid g = shaped_grid({"....", "..x.", "...."});
    auto down = ray(g, 36, 0, 36, 64);
    REQUIRE(down.size() == 1);
    CHECK(down[0].y == 20);
    CHECK(down[0].nx == -1);
    CHECK(down[0].ny == -1);
    auto up = ray(g, 44, 64, 44, 0);
    REQUIRE(up.size() == 1);
    CHECK(up[0].y == 28);
    CHECK(up[0].nx == 1);
    CHECK(up[0].ny == 1);
    CHECK(g.solid_at(40, 16));
    CHECK(g.solid_at(40, 31));
    CHECK(g.solid_at(33, 24));
    CHECK_FALSE(g.solid_at(33, 29));  // below the underside's left slope
    CHECK_FALSE(g.solid_at(35, 20));  // above the top's
}

}  // TEST_SUITE
