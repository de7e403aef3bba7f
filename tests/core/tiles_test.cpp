// SPDX-License-Identifier: MIT
// Bodies against solid tiles: per-axis snap-out (discrete and swept) and the
// ground probe (semantics §4).
#include <vector>

#include "support.hpp"
#include "ground.hpp"
#include "tiles.hpp"

using namespace dst;
using ds::CollisionMode;

namespace {

constexpr CollisionMode kSwept = CollisionMode::Swept;
constexpr CollisionMode kDiscrete = CollisionMode::Discrete;

// A body that has already moved by (vx, vy) this frame.
Body moved(double x, double y, double w, double h, double vx, double vy) {
    Body b = box(x, y, w, h);
    b.vx = I(vx);
    b.vy = I(vy);
    return b;
}

Body standing(double x, double y, double w, double h) {
    Body b = box(x, y, w, h);
    b.gravity = true;
    return b;
}

}  // namespace

TEST_SUITE("tiles") {

// ---- resolve_tile_collisions_x ----------------------------------------------

TEST_CASE("tile x: moving right snaps the right edge to the solid column's left edge") {
    const auto g = grid({"..#."});
    for (auto mode : {kDiscrete, kSwept}) {
        Body b = moved(25, 0, 16, 16, 5, 0);  // [25, 41) reaches column 2
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK_EXACT(b.x, 16);  // 2*16 - 16
        CHECK_EXACT(b.vx, 0);
        CHECK_EXACT(b.y, 0);
        CHECK_EXACT(b.vy, 0);
        CHECK(ds::changed_fields(moved(25, 0, 16, 16, 5, 0), b) ==
              (ds::kFieldX | ds::kFieldVx));
    }
}

TEST_CASE("tile x: moving left snaps the left edge to the solid column's right edge") {
    const auto g = grid({"#..."});
    for (auto mode : {kDiscrete, kSwept}) {
        Body b = moved(10, 0, 16, 16, -5, 0);  // [10, 26) reaches column 0
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK_EXACT(b.x, 16);  // (0+1)*16
        CHECK_EXACT(b.vx, 0);
    }
}

TEST_CASE("tile x: leftmost solid column when moving right, rightmost when moving left") {
    const auto g = grid({".##."});
    Body r = moved(10, 0, 30, 16, 2, 0);  // [10, 40): columns 0..2
    ds::resolve_tile_collisions_x(r, &g, kDiscrete);
    CHECK_EXACT(r.x, -14);  // 1*16 - 30
    CHECK_EXACT(r.vx, 0);
    Body l = moved(10, 0, 30, 16, -2, 0);
    ds::resolve_tile_collisions_x(l, &g, kDiscrete);
    CHECK_EXACT(l.x, 48);  // (2+1)*16
    CHECK_EXACT(l.vx, 0);
}

TEST_CASE("tile x: touching a solid column is not a collision") {
    const auto g = grid({"#.#."});
    for (auto mode : {kDiscrete, kSwept}) {
        const Body r = moved(16, 0, 16, 16, 3, 0);  // [16, 32): right edge on column 2
        Body b = r;
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK(same_body(b, r));
        const Body l = moved(16, 0, 16, 16, -3, 0);  // left edge on column 0's right edge
        Body c = l;
        ds::resolve_tile_collisions_x(c, &g, mode);
        CHECK(same_body(c, l));
    }
}

TEST_CASE("tile x: only the rows the box spans count") {
    const auto g = grid({"..#.", "....", "...."});
    // row 1 only: the solid cell in row 0 is not beside it
    const Body below = moved(25, 16, 16, 16, 5, 0);
    Body b = below;
    ds::resolve_tile_collisions_x(b, &g, kDiscrete);
    CHECK(same_body(b, below));
    // touching row 0 from below ([16, 32)) still does not count
    Body s = moved(25, 16, 16, 16, 5, 0);
    ds::resolve_tile_collisions_x(s, &g, kSwept);
    CHECK(same_body(s, below));
    // one pixel into row 0 does
    Body c = moved(25, 15, 16, 16, 5, 0);
    ds::resolve_tile_collisions_x(c, &g, kDiscrete);
    CHECK_EXACT(c.x, 16);
    CHECK_EXACT(c.vx, 0);
    CHECK_EXACT(c.y, 15);
}

TEST_CASE("tile x: no grid, vx = 0, or skip bit: nothing happens") {
    const auto g = grid({"####"});
    SUBCASE("no grid") {
        const Body before = moved(8, 0, 16, 16, 5, 0);
        Body b = before;
        ds::resolve_tile_collisions_x(b, nullptr, kSwept);
        CHECK(same_body(b, before));
        ds::resolve_tile_collisions_x(b, nullptr, kDiscrete);
        CHECK(same_body(b, before));
    }
    SUBCASE("vx = 0 while inside solid cells") {
        const Body before = moved(8, 0, 16, 16, 0, 5);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_x(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("vx = flonum 0.0 is zero too") {
        Body before = moved(8, 0, 16, 16, 0, 0);
        before.vx = F(0.0);
        Body b = before;
        ds::resolve_tile_collisions_x(b, &g, kSwept);
        CHECK(same_body(b, before));
    }
    SUBCASE("skip tile-collisions-x") {
        Body before = moved(8, 0, 16, 16, 5, 0);
        before.skip = ds::kSkipTileX;
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_x(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("the other skip bits do not stop it") {
        Body b = moved(8, 0, 16, 16, 5, 0);
        b.skip = kEverySkip & ~ds::kSkipTileX;
        ds::resolve_tile_collisions_x(b, &g, kSwept);
        CHECK_EXACT(b.x, -16);  // leftmost solid column 0: 0*16 - 16
        CHECK_EXACT(b.vx, 0);
    }
}

TEST_CASE("tile x: no solid cell found leaves vx alone") {
    const auto g = grid({"....", "...."});
    const Body before = moved(20, 4, 16, 16, 7, 0);
    for (auto mode : {kDiscrete, kSwept}) {
        Body b = before;
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK(same_body(b, before));
    }
}

TEST_CASE("tile x: exactness of the snapped position follows x and w") {
    const auto g = grid({"..#."});
    SUBCASE("flonum x") {
        Body b = moved(0, 0, 16, 16, 5, 0);
        b.x = F(25.5);
        ds::resolve_tile_collisions_x(b, &g, kDiscrete);
        CHECK_FLONUM(b.x, 16);
        CHECK_EXACT(b.vx, 0);
    }
    SUBCASE("flonum w") {
        Body b = moved(25, 0, 16, 16, 5, 0);
        b.w = F(16);
        ds::resolve_tile_collisions_x(b, &g, kDiscrete);
        CHECK_FLONUM(b.x, 16);
        CHECK_EXACT(b.vx, 0);
    }
    SUBCASE("flonum vx only: x and w exact, so x stays exact") {
        Body b = moved(25, 0, 16, 16, 0, 0);
        b.vx = F(5.5);
        ds::resolve_tile_collisions_x(b, &g, kDiscrete);
        CHECK_EXACT(b.x, 16);
        CHECK_EXACT(b.vx, 0);
    }
    SUBCASE("flonum y or h do not matter on the x axis") {
        Body b = moved(25, 0, 16, 16, 5, 0);
        b.y = F(0.5);
        b.h = F(15.0);
        ds::resolve_tile_collisions_x(b, &g, kDiscrete);
        CHECK_EXACT(b.x, 16);
        CHECK_EXACT(b.vx, 0);
        CHECK_FLONUM(b.y, 0.5);
    }
    SUBCASE("flonum x moving left") {
        const auto h = grid({"#..."});
        Body b = moved(0, 0, 16, 16, -1, 0);
        b.x = F(15.75);
        ds::resolve_tile_collisions_x(b, &h, kSwept);
        CHECK_FLONUM(b.x, 16);
        CHECK_EXACT(b.vx, 0);
    }
}

TEST_CASE("tile x: negative coordinates") {
    // map cell (-2, 0) is solid; (-1, 0) is empty
    const auto g = grid({"#."}, 16, 16, -2, 0);
    Body b = moved(-20, 0, 8, 16, -3, 0);  // [-20, -12): columns -2..-1
    ds::resolve_tile_collisions_x(b, &g, kDiscrete);
    CHECK_EXACT(b.x, -16);  // (-2+1)*16
    CHECK_EXACT(b.vx, 0);

    const auto h = grid({".#"}, 16, 16, -2, 0);  // cell (-1, 0) solid
    Body r = moved(-33, 0, 16, 16, 2, 0);        // [-33, -17): columns -3..-2
    const Body rb = r;
    ds::resolve_tile_collisions_x(r, &h, kDiscrete);
    CHECK(same_body(r, rb));
    Body r2 = moved(-20, 0, 16, 16, 2, 0);  // [-20, -4): columns -2..-1
    ds::resolve_tile_collisions_x(r2, &h, kDiscrete);
    CHECK_EXACT(r2.x, -32);  // -1*16 - 16
    CHECK_EXACT(r2.vx, 0);
}

TEST_CASE("tile x: boxes outside the grid and huge coordinates see no cells") {
    const auto g = grid({"####", "####"});
    for (auto mode : {kDiscrete, kSwept}) {
        const Body far = moved(1000, 0, 16, 16, 5, 0);
        Body b = far;
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK(same_body(b, far));
        const Body above = moved(8, -40, 16, 16, 5, 0);
        b = above;
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK(same_body(b, above));
        const Body huge = moved(1e9, 0, 16, 16, 1, 0);
        b = huge;
        ds::resolve_tile_collisions_x(b, &g, mode);
        CHECK(same_body(b, huge));
        Body fl = moved(0, 0, 16, 16, 0, 0);
        fl.x = F(1e12);
        fl.vx = F(-3.0);
        const Body flb = fl;
        ds::resolve_tile_collisions_x(fl, &g, mode);
        CHECK(same_body(fl, flb));
    }
}

TEST_CASE("tile x: zero-size boxes overlap nothing") {
    const auto g = grid({"####"});
    SUBCASE("zero width, discrete") {
        const Body before = moved(24, 0, 0, 16, 5, 0);
        Body b = before;
        ds::resolve_tile_collisions_x(b, &g, kDiscrete);
        CHECK(same_body(b, before));
    }
    SUBCASE("zero height spans no rows, in either mode") {
        const Body before = moved(24, 8, 16, 0, 5, 0);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_x(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("zero size, in either mode") {
        const Body before = moved(24, 8, 0, 0, -40, 0);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_x(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
}

TEST_CASE("tile x: swept stops a box moving 10 tiles per frame at a 1-tile wall") {
    // wall at column 5 ([80, 96)); the box starts at x = 0 and moves 160 px
    const auto g = grid({".....#.............."});
    SUBCASE("discrete tunnels") {
        Body b = moved(160, 0, 16, 16, 160, 0);
        ds::resolve_tile_collisions_x(b, &g, kDiscrete);
        CHECK_EXACT(b.x, 160);
        CHECK_EXACT(b.vx, 160);
    }
    SUBCASE("swept stops at the wall") {
        Body b = moved(160, 0, 16, 16, 160, 0);
        ds::resolve_tile_collisions_x(b, &g, kSwept);
        CHECK_EXACT(b.x, 64);  // 5*16 - 16
        CHECK_EXACT(b.vx, 0);
    }
    SUBCASE("leftward: discrete tunnels, swept stops") {
        // from x = 300 moving -160 to x = 140; the wall at column 12 ([192, 208)) is crossed
        const auto h = grid({"............#......."});
        Body d = moved(140, 0, 16, 16, -160, 0);
        ds::resolve_tile_collisions_x(d, &h, kDiscrete);
        CHECK_EXACT(d.x, 140);
        CHECK_EXACT(d.vx, -160);
        Body s = moved(140, 0, 16, 16, -160, 0);
        ds::resolve_tile_collisions_x(s, &h, kSwept);
        CHECK_EXACT(s.x, 208);  // (12+1)*16
        CHECK_EXACT(s.vx, 0);
    }
    SUBCASE("swept stops at the first wall crossed, not the last") {
        const auto h = grid({"...#...#..#........."});
        Body r = moved(160, 0, 16, 16, 160, 0);  // from 0 to 160
        ds::resolve_tile_collisions_x(r, &h, kSwept);
        CHECK_EXACT(r.x, 32);  // 3*16 - 16
        Body l = moved(16, 0, 16, 16, -160, 0);  // from 176 to 16
        ds::resolve_tile_collisions_x(l, &h, kSwept);
        CHECK_EXACT(l.x, 176);  // (10+1)*16: the wall right beside the start
        CHECK_EXACT(l.vx, 0);
    }
    SUBCASE("a wall in another row is not crossed") {
        const auto h = grid({".....#..............", "...................."});
        const Body before = moved(160, 16, 16, 16, 160, 0);
        Body b = before;
        ds::resolve_tile_collisions_x(b, &h, kSwept);
        CHECK(same_body(b, before));
    }
}

TEST_CASE("tile x: swept at huge speeds does not tunnel either") {
    const auto g = grid({".....#.............."});
    Body b = moved(1e9, 0, 16, 16, 1e9, 0);  // from 0 to 1e9
    ds::resolve_tile_collisions_x(b, &g, kSwept);
    CHECK_EXACT(b.x, 64);
    CHECK_EXACT(b.vx, 0);
    Body f = moved(0, 0, 16, 16, 0, 0);
    f.x = F(1e12);
    f.vx = F(1e12);
    ds::resolve_tile_collisions_x(f, &g, kSwept);
    CHECK_FLONUM(f.x, 64);
    CHECK_EXACT(f.vx, 0);
    Body l = moved(-1e9, 0, 16, 16, -1e9 - 400, 0);  // from x = 400 to -1e9
    ds::resolve_tile_collisions_x(l, &g, kSwept);
    CHECK_EXACT(l.x, 96);
    CHECK_EXACT(l.vx, 0);
}

TEST_CASE("tile x: swept is identical to discrete when |vx| <= w") {
    const auto g = grid({"..#.#...", "........"});
    // a variety of moves no longer than the box
    const double xs[] = {20, 25, 30, 33, 40, 47, 50, 60};
    const double vs[] = {16, 8, 1, -1, -8, -16, 3, -5};
    for (double x : xs) {
        for (double v : vs) {
            Body d = moved(x, 4, 16, 16, v, 0);
            Body s = d;
            ds::resolve_tile_collisions_x(d, &g, kDiscrete);
            ds::resolve_tile_collisions_x(s, &g, kSwept);
            CAPTURE(x);
            CAPTURE(v);
            CHECK(same_body(d, s));
        }
    }
    // vx == w exactly: the crossed region is the box itself
    Body d = moved(16, 0, 16, 16, 16, 0);  // from 0 to 16; column 2 not reached
    Body s = d;
    ds::resolve_tile_collisions_x(d, &g, kDiscrete);
    ds::resolve_tile_collisions_x(s, &g, kSwept);
    CHECK(same_body(d, s));
    CHECK_EXACT(s.x, 16);
    CHECK_EXACT(s.vx, 16);
}

TEST_CASE("tile x: swept with vx just over w reaches one more cell") {
    // from x = 0 (right edge 16) to x = 17 (right edge 33): the edge crossed [16, 33)
    const auto g = grid({".#.."});
    Body d = moved(17, 0, 16, 16, 17, 0);  // [17, 33) is columns 1..2
    ds::resolve_tile_collisions_x(d, &g, kDiscrete);
    CHECK_EXACT(d.x, 0);
    Body s = moved(17, 0, 16, 16, 17, 0);
    ds::resolve_tile_collisions_x(s, &g, kSwept);
    CHECK_EXACT(s.x, 0);
    // the box started beyond the solid column: a small box jumping over column 1
    Body j = moved(40, 0, 4, 16, 30, 0);  // from [10, 14) to [40, 44)
    Body jd = j;
    ds::resolve_tile_collisions_x(jd, &g, kDiscrete);
    CHECK_EXACT(jd.x, 40);
    CHECK_EXACT(jd.vx, 30);
    ds::resolve_tile_collisions_x(j, &g, kSwept);
    CHECK_EXACT(j.x, 12);  // 1*16 - 4
    CHECK_EXACT(j.vx, 0);
}

// ---- resolve_tile_collisions_y ----------------------------------------------

TEST_CASE("tile y: falling snaps the feet to the solid row's top; rising to its bottom") {
    // tiles 16 wide, 8 high
    const auto g = grid({"....", "....", "....", "####"}, 16, 8);
    for (auto mode : {kDiscrete, kSwept}) {
        Body b = moved(8, 12, 16, 16, 0, 5);  // [12, 28): rows 1..3
        ds::resolve_tile_collisions_y(b, &g, mode);
        CHECK_EXACT(b.y, 8);  // 3*8 - 16
        CHECK_EXACT(b.vy, 0);
        CHECK_EXACT(b.x, 8);
    }
    const auto c = grid({"####", "....", "....", "...."}, 16, 8);
    for (auto mode : {kDiscrete, kSwept}) {
        Body b = moved(8, 4, 16, 16, 0, -5);  // [4, 20): rows 0..2
        ds::resolve_tile_collisions_y(b, &c, mode);
        CHECK_EXACT(b.y, 8);  // (0+1)*8
        CHECK_EXACT(b.vy, 0);
    }
}

TEST_CASE("tile y: a wide entity (48 px) over a single solid tile lands on it") {
    // floor row 1 has a single solid cell in column 2; the box spans columns 1..3
    const auto g = grid({".....", "..#.."});
    for (auto mode : {kDiscrete, kSwept}) {
        Body b = moved(16, 5, 48, 16, 0, 5);
        ds::resolve_tile_collisions_y(b, &g, mode);
        CHECK_EXACT(b.y, 0);  // 1*16 - 16
        CHECK_EXACT(b.vy, 0);
        CHECK_EXACT(b.x, 16);
    }
}

TEST_CASE("tile y: topmost solid row when falling, bottommost when rising") {
    const auto g = grid({".", "#", "#", "."});
    Body f = moved(0, 8, 16, 40, 0, 1);  // [8, 48): rows 0..2
    ds::resolve_tile_collisions_y(f, &g, kDiscrete);
    CHECK_EXACT(f.y, -24);  // 1*16 - 40
    Body r = moved(0, 8, 16, 40, 0, -1);
    ds::resolve_tile_collisions_y(r, &g, kDiscrete);
    CHECK_EXACT(r.y, 48);  // (2+1)*16
}

TEST_CASE("tile y: no grid, vy = 0, skip bit, touching, outside") {
    const auto g = grid({"....", "####"});
    SUBCASE("no grid") {
        const Body before = moved(0, 8, 16, 16, 0, 3);
        Body b = before;
        ds::resolve_tile_collisions_y(b, nullptr, kSwept);
        CHECK(same_body(b, before));
    }
    SUBCASE("vy = 0 inside the floor") {
        const Body before = moved(0, 8, 16, 16, 3, 0);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_y(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("skip tile-collisions-y") {
        Body before = moved(0, 8, 16, 16, 0, 3);
        before.skip = ds::kSkipTileY;
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_y(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("skip tile-collisions-x does not stop the y pass") {
        Body b = moved(0, 8, 16, 16, 0, 3);
        b.skip = kEverySkip & ~ds::kSkipTileY;
        ds::resolve_tile_collisions_y(b, &g, kDiscrete);
        CHECK_EXACT(b.y, 0);
        CHECK_EXACT(b.vy, 0);
    }
    SUBCASE("standing exactly on the floor is touching, not overlapping") {
        const Body before = moved(0, 0, 16, 16, 0, 1);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_y(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("beside the grid") {
        const Body before = moved(64, 8, 16, 16, 0, 3);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_y(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
    SUBCASE("zero width spans no columns") {
        const Body before = moved(8, 8, 0, 16, 0, 3);
        for (auto mode : {kDiscrete, kSwept}) {
            Body b = before;
            ds::resolve_tile_collisions_y(b, &g, mode);
            CHECK(same_body(b, before));
        }
    }
}

TEST_CASE("tile y: exactness of the snapped position follows y and h") {
    const auto g = grid({"....", "####"});
    Body a = moved(0, 0, 16, 16, 0, 3);
    a.y = F(8.5);
    ds::resolve_tile_collisions_y(a, &g, kDiscrete);
    CHECK_FLONUM(a.y, 0);
    CHECK_EXACT(a.vy, 0);
    Body b = moved(0, 8, 16, 16, 0, 3);
    b.h = F(16);
    ds::resolve_tile_collisions_y(b, &g, kDiscrete);
    CHECK_FLONUM(b.y, 0);
    CHECK_EXACT(b.vy, 0);
    Body c = moved(0, 8, 16, 16, 0, 0);
    c.vy = F(2.5);
    c.x = F(0.5);
    ds::resolve_tile_collisions_y(c, &g, kDiscrete);
    CHECK_EXACT(c.y, 0);
    CHECK_EXACT(c.vy, 0);
}

TEST_CASE("tile y: negative rows") {
    // 1 × 1 grid whose cell is map cell (0, -3): [0,16) × [-48, -32)
    const auto g = grid({"#"}, 16, 16, 0, -3);
    Body up = moved(0, -40, 16, 16, 0, -6);  // [-40, -24): rows -3..-2
    ds::resolve_tile_collisions_y(up, &g, kSwept);
    CHECK_EXACT(up.y, -32);
    CHECK_EXACT(up.vy, 0);
    Body down = moved(0, -60, 16, 16, 0, 6);  // [-60, -44): rows -4..-3
    ds::resolve_tile_collisions_y(down, &g, kDiscrete);
    CHECK_EXACT(down.y, -64);  // -3*16 - 16
    CHECK_EXACT(down.vy, 0);
}

TEST_CASE("tile y: swept stops a fast fall at a 1-tile floor; discrete tunnels") {
    std::vector<std::string> rows;
    for (int r = 0; r < 20; ++r) rows.emplace_back(r == 5 ? "#" : ".");  // floor: row 5, [80, 96)
    const auto g = grid(rows);
    Body d = moved(0, 160, 16, 16, 0, 160);
    ds::resolve_tile_collisions_y(d, &g, kDiscrete);
    CHECK_EXACT(d.y, 160);
    CHECK_EXACT(d.vy, 160);
    Body s = moved(0, 160, 16, 16, 0, 160);
    ds::resolve_tile_collisions_y(s, &g, kSwept);
    CHECK_EXACT(s.y, 64);
    CHECK_EXACT(s.vy, 0);
    Body u = moved(0, 0, 16, 16, 0, -160);  // from y = 160 up to 0
    ds::resolve_tile_collisions_y(u, &g, kSwept);
    CHECK_EXACT(u.y, 96);
    CHECK_EXACT(u.vy, 0);
}

// ---- tile_supports ----------------------------------------------------------

TEST_CASE("tile_supports: a solid cell in the row under the feet") {
    const auto g = grid({"....", "#..."});
    CHECK(ds::tile_supports(box(0, 0, 16, 16), g));       // feet at 16: row 1
    CHECK(ds::tile_supports(box(0, 1, 16, 16), g));       // sunk 1 px
    CHECK_FALSE(ds::tile_supports(box(0, -1, 16, 16), g));  // feet at 15: row 0
    CHECK_FALSE(ds::tile_supports(box(16, 0, 16, 16), g));  // over the empty column 1
    CHECK(ds::tile_supports(box(15, 0, 16, 16), g));        // one pixel over column 0
    CHECK_FALSE(ds::tile_supports(box(-16, 0, 16, 16), g));  // touching column 0's left edge
    CHECK_FALSE(ds::tile_supports(box(0, 16, 16, 16), g));   // feet at 32: row 2, outside
    Body fy = box(0, 0, 16, 16);
    fy.y = F(-0.5);  // feet at 15.5
    CHECK_FALSE(ds::tile_supports(fy, g));
    fy.y = F(0.0);
    CHECK(ds::tile_supports(fy, g));
}

TEST_CASE("tile_supports: a 48 px entity over a single solid tile") {
    // only column 2 of row 1 is solid; the corners of [16, 64) are in columns 1 and 3
    const auto g = grid({".....", "..#.."});
    CHECK(ds::tile_supports(box(16, 0, 48, 16), g));
    CHECK_FALSE(ds::tile_supports(box(48, 0, 48, 16), g));  // [48, 96): columns 3..5
    CHECK_FALSE(ds::tile_supports(box(-16, 0, 48, 16), g));  // [-16, 32): columns -1..1
}

TEST_CASE("tile_supports: zero width and negative coordinates") {
    const auto g = grid({"####", "####"});
    CHECK_FALSE(ds::tile_supports(box(8, 0, 0, 16), g));
    const auto n = grid({"#"}, 16, 16, -1, -1);  // map cell (-1, -1)
    CHECK(ds::tile_supports(box(-16, -32, 16, 16), n));
    CHECK(ds::tile_supports(box(-1, -32, 1, 16), n));
    CHECK_FALSE(ds::tile_supports(box(0, -32, 16, 16), n));
    CHECK_FALSE(ds::tile_supports(box(-16, -33, 16, 16), n));
}

// ---- entity_supports --------------------------------------------------------

TEST_CASE("entity_supports: resting on a solid body's top") {
    const Body platform = solid_box(0, 16, 32, 8);
    CHECK(ds::entity_supports(box(8, 0, 16, 16), platform));
    CHECK(ds::entity_supports(standing(8, 0, 16, 16), wall_box(0, 16, 32, 8)));
}

TEST_CASE("entity_supports: horizontal overlap is strict") {
    const Body p = solid_box(0, 16, 32, 8);
    CHECK(ds::entity_supports(box(31, 0, 16, 16), p));
    CHECK_FALSE(ds::entity_supports(box(32, 0, 16, 16), p));   // touching the right edge
    CHECK(ds::entity_supports(box(-15, 0, 16, 16), p));
    CHECK_FALSE(ds::entity_supports(box(-16, 0, 16, 16), p));  // touching the left edge
    // the overlap test is the literal strict formula: a zero-width body strictly
    // inside the top's span overlaps it (unlike tiles, where width 0 spans no column)
    CHECK(ds::entity_supports(box(8, 0, 0, 16), p));
    CHECK_FALSE(ds::entity_supports(box(0, 0, 0, 16), p));  // on the left edge: 0 < 0 fails
}

TEST_CASE("entity_supports: feet within 4 px of the top, inclusive") {
    const Body p = solid_box(0, 16, 32, 8);
    CHECK(ds::entity_supports(box(8, -4, 16, 16), p));   // 4 above
    CHECK(ds::entity_supports(box(8, 4, 16, 16), p));    // 4 sunk in
    CHECK_FALSE(ds::entity_supports(box(8, -5, 16, 16), p));
    CHECK_FALSE(ds::entity_supports(box(8, 5, 16, 16), p));
    Body a = box(8, 0, 16, 16);
    a.y = F(-4.5);
    CHECK_FALSE(ds::entity_supports(a, p));
    a.y = F(4.5);
    CHECK_FALSE(ds::entity_supports(a, p));
    a.y = F(-4.0);
    CHECK(ds::entity_supports(a, p));
    a.y = F(3.75);
    CHECK(ds::entity_supports(a, p));
}

TEST_CASE("entity_supports: vertical speeds within 4 px/frame, inclusive") {
    Body p = solid_box(0, 16, 32, 8);
    Body b = box(8, 0, 16, 16);
    b.vy = I(4);
    CHECK(ds::entity_supports(b, p));
    b.vy = I(-4);
    CHECK(ds::entity_supports(b, p));
    b.vy = F(4.5);
    CHECK_FALSE(ds::entity_supports(b, p));
    b.vy = I(5);
    CHECK_FALSE(ds::entity_supports(b, p));
    // a moving platform carries a body moving with it
    p.vy = I(10);
    b.vy = I(12);
    CHECK(ds::entity_supports(b, p));
    b.vy = I(15);
    CHECK_FALSE(ds::entity_supports(b, p));
    b.vy = F(5.5);
    CHECK_FALSE(ds::entity_supports(b, p));
    b.vy = I(6);
    CHECK(ds::entity_supports(b, p));
}

TEST_CASE("entity_supports: the other body must be solid and not a ghost") {
    Body p = box(0, 16, 32, 8);
    CHECK_FALSE(ds::entity_supports(box(8, 0, 16, 16), p));  // not solid
    p.solid = true;
    p.skip = ds::kSkipEntityCollisions;
    CHECK_FALSE(ds::entity_supports(box(8, 0, 16, 16), p));
    p.skip = kEverySkip & ~ds::kSkipEntityCollisions;
    CHECK(ds::entity_supports(box(8, 0, 16, 16), p));
}

// ---- detect_on_solid --------------------------------------------------------

TEST_CASE("detect_on_solid: tile support sets on_ground") {
    const auto g = grid({"....", "####"});
    Body b = standing(0, 0, 16, 16);
    ds::detect_on_solid(b, {}, -1, &g);
    CHECK(b.on_ground);
    CHECK(ds::changed_fields(standing(0, 0, 16, 16), b) == ds::kFieldOnGround);
}

TEST_CASE("detect_on_solid: writes false when nothing supports") {
    const auto g = grid({"....", "####"});
    Body b = standing(0, -10, 16, 16);
    b.on_ground = true;
    ds::detect_on_solid(b, {}, -1, &g);
    CHECK_FALSE(b.on_ground);
    Body n = standing(0, 0, 16, 16);
    n.on_ground = true;
    ds::detect_on_solid(n, {}, -1, nullptr);  // no grid, no scene
    CHECK_FALSE(n.on_ground);
    const Body off = standing(0, -10, 16, 16);
    Body o = off;
    ds::detect_on_solid(o, {}, -1, &g);
    CHECK(same_body(o, off));
}

TEST_CASE("detect_on_solid: a wide entity over one solid tile") {
    const auto g = grid({".....", "..#.."});
    Body b = standing(16, 0, 48, 16);
    ds::detect_on_solid(b, {}, -1, &g);
    CHECK(b.on_ground);
    Body z = standing(32, 0, 0, 16);  // zero width: no tile support
    z.on_ground = true;
    ds::detect_on_solid(z, {}, -1, &g);
    CHECK_FALSE(z.on_ground);
}

TEST_CASE("detect_on_solid: needs gravity? and is skipped by 'on-solid") {
    const auto g = grid({"....", "####"});
    SUBCASE("gravity false keeps the old flag, right or wrong") {
        Body b = box(0, 0, 16, 16);
        ds::detect_on_solid(b, {}, -1, &g);
        CHECK_FALSE(b.on_ground);
        Body c = box(0, -10, 16, 16);
        c.on_ground = true;
        ds::detect_on_solid(c, {}, -1, &g);
        CHECK(c.on_ground);
    }
    SUBCASE("skip on-solid") {
        Body b = standing(0, 0, 16, 16);
        b.skip = ds::kSkipOnSolid;
        const Body before = b;
        ds::detect_on_solid(b, {}, -1, &g);
        CHECK(same_body(b, before));
        CHECK_FALSE(b.on_ground);
    }
    SUBCASE("the other skip bits do not stop it") {
        Body b = standing(0, 0, 16, 16);
        b.skip = kEverySkip & ~ds::kSkipOnSolid;
        ds::detect_on_solid(b, {}, -1, &g);
        CHECK(b.on_ground);
    }
}

TEST_CASE("detect_on_solid: standing on a solid scene body, without a tilemap") {
    std::vector<Body> scene = {solid_box(0, 16, 32, 8), standing(8, 0, 16, 16)};
    Body b = scene[1];
    ds::detect_on_solid(b, scene, 1, nullptr);
    CHECK(b.on_ground);
    // the same body one pixel too high for the tolerance
    Body h = standing(8, -5, 16, 16);
    ds::detect_on_solid(h, scene, 1, nullptr);
    CHECK_FALSE(h.on_ground);
}

TEST_CASE("detect_on_solid: the body's own slot is excluded") {
    // a 4 px tall solid body would support itself: feet at 4, its own top at 0
    Body b = standing(0, 0, 16, 4);
    b.solid = true;
    REQUIRE(ds::entity_supports(b, b));
    std::vector<Body> scene = {b};
    Body self = b;
    ds::detect_on_solid(self, scene, 0, nullptr);
    CHECK_FALSE(self.on_ground);
    // as another slot (no id) the same body counts
    Body other = b;
    ds::detect_on_solid(other, scene, -1, nullptr);
    CHECK(other.on_ground);
}

TEST_CASE("detect_on_solid: a scene body with the same nonzero id is excluded") {
    Body platform = solid_box(0, 16, 32, 8);
    platform.id = 5;
    std::vector<Body> scene = {platform};
    Body b = standing(8, 0, 16, 16);
    SUBCASE("equal id") {
        b.id = 5;
        ds::detect_on_solid(b, scene, -1, nullptr);
        CHECK_FALSE(b.on_ground);
    }
    SUBCASE("different id") {
        b.id = 6;
        ds::detect_on_solid(b, scene, -1, nullptr);
        CHECK(b.on_ground);
    }
    SUBCASE("no id on the body") {
        b.id = 0;
        ds::detect_on_solid(b, scene, -1, nullptr);
        CHECK(b.on_ground);
    }
    SUBCASE("id 0 on both is not an identity") {
        scene[0].id = 0;
        b.id = 0;
        ds::detect_on_solid(b, scene, -1, nullptr);
        CHECK(b.on_ground);
    }
    SUBCASE("an equal-id body does not hide another supporter") {
        Body other = solid_box(0, 16, 32, 8);
        other.id = 9;
        scene.push_back(other);
        b.id = 5;
        ds::detect_on_solid(b, scene, -1, nullptr);
        CHECK(b.on_ground);
    }
}

TEST_CASE("detect_on_solid: tolerance boundaries through the scene") {
    const std::vector<Body> scene = {solid_box(0, 16, 32, 8)};
    auto on = [&](Body b) {
        ds::detect_on_solid(b, scene, -1, nullptr);
        return b.on_ground;
    };
    Body b = standing(8, -4, 16, 16);
    CHECK(on(b));
    b.y = F(-4.5);
    CHECK_FALSE(on(b));
    b.y = I(4);
    CHECK(on(b));
    b.y = F(4.5);
    CHECK_FALSE(on(b));
    b = standing(8, 0, 16, 16);
    b.vy = I(4);
    CHECK(on(b));
    b.vy = F(4.5);
    CHECK_FALSE(on(b));
    b.vy = I(-4);
    CHECK(on(b));
    b.vy = F(-4.5);
    CHECK_FALSE(on(b));
}

TEST_CASE("detect_on_solid: non-solid and ghost scene bodies do not support") {
    Body ghost = solid_box(0, 16, 32, 8);
    ghost.skip = ds::kSkipEntityCollisions;
    const std::vector<Body> scene = {box(0, 16, 32, 8), ghost};
    Body b = standing(8, 0, 16, 16);
    b.on_ground = true;
    ds::detect_on_solid(b, scene, -1, nullptr);
    CHECK_FALSE(b.on_ground);
}

TEST_CASE("detect_on_solid: tile or entity, either is enough") {
    const auto g = grid({"....", "#..."});
    const std::vector<Body> scene = {solid_box(32, 16, 32, 8)};
    Body t = standing(0, 0, 16, 16);  // over the tile, not the body
    ds::detect_on_solid(t, scene, -1, &g);
    CHECK(t.on_ground);
    Body e = standing(40, 0, 16, 16);  // over the body, not a tile
    ds::detect_on_solid(e, scene, -1, &g);
    CHECK(e.on_ground);
    Body n = standing(20, 0, 8, 16);  // [20, 28): neither
    ds::detect_on_solid(n, scene, -1, &g);
    CHECK_FALSE(n.on_ground);
}

}  // TEST_SUITE
