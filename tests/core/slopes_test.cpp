// Shaped cells (semantics §12): ramps and part-tile boxes, walked on,
// landed on, bumped into; every figure worked out by hand from the rule.
#include <algorithm>
#include <string>
#include <vector>

#include "frame.hpp"
#include "ground.hpp"
#include "support.hpp"
#include "tiles.hpp"

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

// '/' 45° up to the right, '\' 45° up to the left; 'a' 'b' the lower and
// upper tiles of a 1:2 ramp up to the right, 'd' 'c' the same up to the
// left; 'v' a 45° ceiling ramp (the '/' tile flipped vertically), '^' its
// mirror; '_' a half-height box at the bottom, '-' a 4 px ledge at the top;
// 'o' a one-way '/'.
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

}  // TEST_SUITE
