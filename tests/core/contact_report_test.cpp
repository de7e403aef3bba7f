// The core's part of the contact report (semantics §10): the sides the tile
// steps stopped a #:contacts? body on, the pairs a frame logs, the supporter
// ground detection names, and that such a body never sleeps.
#include <utility>
#include <vector>

#include "contacts.hpp"
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
