// SPDX-License-Identifier: MIT
// The core's part of the contact report (semantics §10): the sides the tile
// steps stopped a #:contacts? body on, the pairs a frame logs, the supporter
// ground detection names, and that such a body never sleeps.
#include <utility>
#include <vector>

#include "contacts.hpp"
#include "detail/unwritten.hpp"
#include "frame.hpp"
#include "ground.hpp"
#include "settle.hpp"
#include "support.hpp"
#include "tiles.hpp"

using namespace dst;
using ds::CollisionMode;

namespace {

Body reporting(Body b) {
    b.contacts = true;
    return b;
}

Body moving(double x, double y, double vx, double vy) {
    Body b = reporting(box(x, y, 16, 16));
    b.vx = I(vx);
    b.vy = I(vy);
    return b;
}

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

Pairs pairs_of(const ds::Frame& f) {
    const auto p = f.contact_pairs();
    return Pairs(p.begin(), p.end());
}

}  // namespace

TEST_SUITE("contact-report") {

TEST_CASE("each tile step sets its own axis's sides, and only on a body that opts in") {
    const auto g = grid({"..#.", "....", "....", "####"});
    Body b = moving(17, 0, 5, 0);  // [17, 33) reaches column 2
    ds::resolve_tile_collisions_x(b, &g, CollisionMode::Swept);
    CHECK(b.blocked == ds::kSideRight);
    Body plain = b;
    plain.contacts = false;
    plain.blocked = 0;
    plain.vx = I(5);
    plain.x = I(17);
    ds::resolve_tile_collisions_x(plain, &g, CollisionMode::Swept);
    CHECK(plain.blocked == 0);
    b.y = I(34);  // falls into row 3; vx is 0 now: the x step clears its part
    b.vy = I(4);
    ds::resolve_tile_collisions_y(b, &g, CollisionMode::Swept);
    CHECK(b.blocked == (ds::kSideRight | ds::kSideDown));
    ds::resolve_tile_collisions_x(b, &g, CollisionMode::Swept);
    CHECK(b.blocked == ds::kSideDown);
}

TEST_CASE("a written side list replaces the unwritten mark; a later sub-frame adds") {
    const auto g = grid({"....", "####"});
    Body b = moving(0, 2, 0, 2);
    b.blocked = ds::kSidesUnwritten;
    ds::resolve_tile_collisions_x(b, &g, CollisionMode::Swept);
    CHECK(b.blocked == 0);
    ds::SubStep later = ds::SubStep::of_frame(2);
    later.gather = true;
    b.blocked = ds::kSideLeft;
    ds::resolve_tile_collisions_y(b, &g, CollisionMode::Swept, later);
    CHECK(b.blocked == (ds::kSideLeft | ds::kSideDown));
}

TEST_CASE("a frame logs its pairs only when a body reports contacts") {
    ds::World w;
    w.bodies = {solid_box(0, 0, 10, 10), solid_box(6, 0, 10, 10)};
    ds::Frame f;
    f.step(w, {});
    CHECK(f.contact_pairs().empty());
    w.bodies = {reporting(solid_box(0, 0, 10, 10)), solid_box(6, 0, 10, 10), solid_box(100, 0, 10, 10)};
    w.bodies[0].touching = ds::kReportUnwritten;
    f.step(w, {});
    CHECK(pairs_of(f) == Pairs{{0, 1}});
    CHECK(w.bodies[0].touching == 0);
}

TEST_CASE("the overlay's log still gets every pair while contacts are logged") {
    ds::PairLog overlay;
    ds::World w;
    w.bodies = {solid_box(0, 0, 10, 10), reporting(solid_box(6, 0, 10, 10))};
    ds::Frame f;
    f.note_pairs(&overlay);
    f.step(w, {});
    CHECK(overlay == ds::PairLog{{0, 1}});
    CHECK(pairs_of(f) == Pairs{{0, 1}});
}

TEST_CASE("push-apart returns the side of the first body that met the second, as it pushed the pair") {
    using ds::kSideDown, ds::kSideLeft, ds::kSideRight, ds::kSideUp;
    Body a = solid_box(0, 0, 10, 10), b = solid_box(2, 6, 10, 10);  // ox 8, oy 4: along y, a above
    CHECK(ds::resolve_pair(a, b) == kSideDown);
    a = solid_box(7, 1, 10, 10), b = solid_box(0, 0, 10, 10);  // ox 3, oy 9: along x, a on the right
    CHECK(ds::resolve_pair(a, b) == kSideLeft);
    a = solid_box(0, 0, 10, 10), b = solid_box(0, 0, 10, 10);  // ox = oy: along y; centres tie: a goes up
    CHECK(ds::resolve_pair(a, b) == kSideDown);
    CHECK(a.y.v == -5);
    // An immovable body first: its side is the opposite of the mover's.
    // Landing wins while the mover's centre is above the wall's, even where
    // the overlap is narrower along x (ox 3, oy 4).
    Body wall = wall_box(0, 10, 30, 10), m = solid_box(27, 4, 10, 10);
    CHECK(ds::resolve_pair(wall, m) == kSideUp);
    CHECK(m.y.v == 0);
    wall = wall_box(0, 10, 30, 10), m = solid_box(25, 12, 10, 10);  // below the centre: ox 5 < oy 8, pushed right
    CHECK(ds::resolve_pair(wall, m) == kSideRight);
    CHECK(m.x.v == 30);
    // Two immovable bodies do not move: least penetration (ox 10, oy 2: along y).
    Body w1 = wall_box(0, 8, 10, 10), w2 = wall_box(0, 0, 10, 10);
    CHECK(ds::resolve_pair(w1, w2) == kSideUp);
    CHECK(ds::opposite_side(kSideLeft) == kSideRight);
    CHECK(ds::opposite_side(kSideDown) == kSideUp);
}

TEST_CASE("a still sensor's pair takes the overlap's axis of least penetration, facing the other's centre") {
    Body s = box(0, 0, 10, 10), b = solid_box(8, 2, 10, 10);  // ox 2 < oy 8
    s.sensor = true;
    CHECK(ds::meet(s, b, false, false) == ds::kSideRight);
    CHECK(ds::meet(b, s, false, false) == ds::kSideLeft);
    Body t = box(0, 0, 10, 10);
    t.sensor = true;
    CHECK(ds::meet(s, t, false, false) == 0);  // two sensors never meet
    CHECK(b.x.v == 8);                         // and nothing moved
}

TEST_CASE("a sensor's pair met by a moving body takes the axis its overlap began on last") {
    // A fast fall onto a corner: ox 5, oy 9, relative speed 4 across and 13
    // down. x overlapped 5/4 frames ago, y 9/13: y is the younger, from above.
    Body walker = box(254, 226, 12, 14), player = solid_box(246, 219, 12, 16);
    walker.sensor = true;
    walker.vx = I(-1);
    player.vx = I(3);
    player.vy = I(13);
    CHECK(ds::meet(player, walker, false, false) == ds::kSideDown);
    CHECK(ds::meet(walker, player, false, false) == ds::kSideUp);
    // Still, it would be the narrower overlap: x, the player on the left.
    player.vx = I(0), player.vy = I(0), walker.vx = I(0);
    CHECK(ds::meet(player, walker, false, false) == ds::kSideRight);
    // Moving only across (5·0 < 9·4): x as well.
    player.vx = I(3);
    CHECK(ds::meet(player, walker, false, false) == ds::kSideRight);
}

TEST_CASE("a frame logs each pair's side beside it, sub-frame after sub-frame") {
    ds::World w;
    // A falls onto a wall and lands on it in each sub-frame: down each time.
    w.bodies = {reporting(solid_box(0, 0, 10, 10)), wall_box(0, 9, 10, 10)};
    w.bodies[0].vy = I(2);
    w.bodies[0].gravity = true;
    ds::Frame f;
    ds::FrameOptions opts;
    opts.substeps = 2;
    f.step(w, opts);
    const auto sides = f.contact_sides();
    CHECK(pairs_of(f) == Pairs{{0, 1}, {0, 1}});
    CHECK(std::vector<uint8_t>(sides.begin(), sides.end()) == std::vector<uint8_t>{ds::kSideDown, ds::kSideDown});
    w.bodies = {solid_box(0, 0, 10, 10), wall_box(0, 9, 10, 10)};
    f.step(w, {});
    CHECK(f.contact_sides().empty());  // nobody reports: nothing logged
}

TEST_CASE("standing on names the first holder in list order, by index + 1") {
    ds::World w;
    Body hero = reporting(solid_box(0, 10, 10, 10));
    hero.gravity = true;
    w.bodies = {box(50, 0, 5, 5), wall_box(0, 20, 40, 10), hero};
    ds::Frame f;
    f.step(w, {});
    CHECK(w.bodies[2].standing_on == 2);  // the wall, at index 1
    std::vector<Body> scene = {wall_box(0, 20, 40, 10)};
    CHECK(ds::first_supporter(w.bodies[2], scene, -1) == 0);
}

TEST_CASE("a body that reports contacts never settles") {
    Body still = box(0, 0, 8, 8);
    CHECK_FALSE(ds::depends_on_others(still, false));
    CHECK(ds::depends_on_others(reporting(still), false));
}

}  // TEST_SUITE
