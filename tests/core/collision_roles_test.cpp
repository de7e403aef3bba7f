// SPDX-License-Identifier: MIT
// Who collides with whom, and how (semantics §13): categories and masks,
// sensors, bounce — in the core, where the bindings' bits arrive.
#include <algorithm>
#include <random>
#include <vector>

#include "bounce.hpp"
#include "contacts.hpp"
#include "detail/contact_scratch.hpp"
#include "frame.hpp"
#include "ground.hpp"
#include "tiles.hpp"
#include "support.hpp"

using namespace dst;
using ds::PairMethod;
using ds::FrameOptions;
using ds::World;

namespace {

// Category indices and their bits.
constexpr uint8_t kDefault = 0, kPlayer = 1, kEnemy = 2, kWall = 3;
constexpr uint64_t bit(uint8_t index) { return uint64_t{1} << index; }

Body in(Body b, uint8_t category, uint64_t mask = ~uint64_t{0}) {
    b.category.index = category;
    b.collides_with.bits = mask;
    return b;
}

Body sensor(Body b) {
    b.sensor = true;
    return b;
}

FrameOptions frame_opts() {
    FrameOptions o;
    o.dt = 1000.0 / 60.0;
    return o;
}

}  // namespace

TEST_SUITE("collision-roles") {

TEST_CASE("categories meet when each one's mask names the other's category") {
    CHECK(ds::categories_meet(solid_box(0, 0, 1, 1), solid_box(0, 0, 1, 1)));  // default, all
    CHECK(ds::categories_meet(in(box(0, 0, 1, 1), kPlayer), in(box(0, 0, 1, 1), kEnemy, bit(kPlayer))));
    CHECK_FALSE(ds::categories_meet(in(box(0, 0, 1, 1), kEnemy, bit(kPlayer)), in(box(0, 0, 1, 1), kEnemy, bit(kPlayer))));
    CHECK_FALSE(ds::categories_meet(in(box(0, 0, 1, 1), kPlayer), in(box(0, 0, 1, 1), kDefault, 0)));
    CHECK_FALSE(ds::collision_eligible(in(solid_box(0, 0, 10, 10), kEnemy, bit(kPlayer)),
                                       in(solid_box(5, 0, 10, 10), kEnemy, bit(kPlayer))));
}

TEST_CASE("push-apart leaves alone the pairs whose categories do not meet") {
    std::vector<Body> v = {in(solid_box(0, 0, 10, 10), kEnemy, bit(kPlayer) | bit(kWall)),
                           in(solid_box(5, 0, 10, 10), kEnemy, bit(kPlayer) | bit(kWall)),
                           in(solid_box(12, 0, 10, 10), kPlayer)};
    ds::resolve_entity_collisions(v);
    CHECK_EXACT(v[0].x, 0);   // the two enemies overlap still
    CHECK_EXACT(v[1].x, 3);   // the player pushed the second: overlap 3 on x, ⌈3/2⌉ = 2 for it
    CHECK_EXACT(v[2].x, 13);
}

TEST_CASE("a sensor is noted with the bodies it overlaps and moves nobody") {
    std::vector<Body> v = {sensor(box(0, 0, 10, 10)), solid_box(5, 0, 10, 10), solid_box(8, 0, 10, 10),
                           sensor(box(2, 0, 10, 10)), box(3, 0, 10, 10)};
    ds::ContactScratch scratch;
    ds::PairLog log;
    scratch.log = &log;
    ds::resolve_entity_collisions(scratch, v);
    // The two solids push each other; each sensor is noted with each solid it
    // overlaps when its turn comes; never with the other sensor or the body
    // that is not solid.
    const ds::PairLog expected = {{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}};
    CHECK(log == expected);
    CHECK_EXACT(v[0].x, 0);
    CHECK_EXACT(v[3].x, 2);
    CHECK_EXACT(v[1].x, 1);  // the solids overlapped by 7 on x: the earlier moves ⌈7/2⌉ left
    CHECK_EXACT(v[2].x, 11);
}

TEST_CASE("the grid pass equals the all-pairs pass with categories, sensors and bounce") {
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        std::mt19937_64 rng(seed);
        auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<uint64_t>(n)); };
        std::vector<Body> a;
        const int n = 20 + pick(300);
        for (int k = 0; k < n; ++k) {
            Body b = solid_box(pick(200), pick(200), 4 + pick(12), 4 + pick(12));
            b.vx = I(pick(9) - 4);
            b.vy = I(pick(9) - 4);
            b.immovable = pick(8) == 0;
            b.category.index = static_cast<uint8_t>(pick(4));
            if (pick(3) == 0) b.collides_with.bits = static_cast<uint64_t>(pick(16));
            b.sensor = pick(10) == 0;
            if (pick(4) == 0) b.bounce = ds::UnitNum::of(pick(2) ? I(1) : F(0.5));
            a.push_back(b);
        }
        std::vector<Body> b = a;
        ds::ContactScratch sa, sb;
        ds::PairLog la, lb;
        sa.log = &la;
        sb.log = &lb;
        ds::resolve_entity_collisions(sa, a, PairMethod::AllPairs);
        ds::resolve_entity_collisions(sb, b, PairMethod::Grid);
        INFO("seed " << seed);
        REQUIRE(la == lb);
        for (int k = 0; k < n; ++k) REQUIRE(same_body(a[k], b[k]));
    }
}

TEST_CASE("ground: a supporter holds up only the bodies it meets") {
    const std::vector<Body> scene = {in(wall_box(0, 20, 40, 10), kWall, bit(kPlayer) | bit(kEnemy))};
    Body player = in(box(5, 10, 10, 10), kPlayer);
    player.gravity = true;
    CHECK(ds::detect_on_solid(player, scene, -1, nullptr));
    CHECK(player.on_ground);
    Body ghost = in(box(5, 10, 10, 10), kDefault);
    ghost.gravity = true;
    ds::detect_on_solid(ghost, scene, -1, nullptr);
    CHECK_FALSE(ghost.on_ground);
    // A sensor holds nobody up.
    Body rider = box(5, 10, 10, 10);
    rider.gravity = true;
    const std::vector<Body> pad = {sensor(wall_box(0, 20, 40, 10))};
    ds::detect_on_solid(rider, pad, -1, nullptr);
    CHECK_FALSE(rider.on_ground);
}

TEST_CASE("UnitNum keeps a bounce's value and exactness in 8 bytes") {
    static_assert(sizeof(ds::UnitNum) == 8);
    CHECK_EXACT(ds::UnitNum::of(I(1)).num(), 1);
    CHECK_FLONUM(ds::UnitNum::of(F(1)).num(), 1);
    CHECK_FLONUM(ds::UnitNum::of(F(0.25)).num(), 0.25);
    CHECK_EXACT(ds::UnitNum{}.num(), 0);
}

TEST_CASE("rebound: −v·bounce, exact when both are, 0 at rest speed or below") {
    CHECK_EXACT(ds::rebound(I(9), I(1)), -9);
    CHECK_EXACT(ds::rebound(I(-9), I(1)), 9);
    CHECK_FLONUM(ds::rebound(I(9), F(0.5)), -4.5);
    CHECK_FLONUM(ds::rebound(F(9), I(1)), -9);
    CHECK_EXACT(ds::rebound(I(9), I(0)), 0);
    CHECK_EXACT(ds::rebound(I(1), I(1)), 0);      // a body at rest on a floor hits at 1
    CHECK_EXACT(ds::rebound(F(-1), F(1)), 0);
    CHECK_FLONUM(ds::rebound(F(1.5), F(1)), -1.5);
}

TEST_CASE("a tile stop rebounds; a carried move does not") {
    const auto g = grid({"....", "....", "....", "####"});
    Body b = box(0, 44, 8, 8);  // feet at 52: 4 into the floor
    b.vy = I(8);
    b.bounce = ds::UnitNum::of(I(1));
    CHECK(ds::resolve_tile_collisions_y(b, &g, ds::CollisionMode::Swept));
    CHECK_EXACT(b.y, 40);
    CHECK_EXACT(b.vy, -8);
    Body carried = box(0, 44, 8, 8);
    carried.vy = I(8);
    carried.bounce = ds::UnitNum::of(I(1));
    ds::SubStep s;
    s.carried = true;
    ds::resolve_tile_collisions_y(carried, &g, ds::CollisionMode::Swept, s);
    CHECK_EXACT(carried.vy, 0);
}

TEST_CASE("bounce 1 on a floor: the same 18-frame bounce for ever, in a Frame") {
    const auto g = grid({"..........", "..........", "..........", "..........", "..........",
                         "..........", "..........", "..........", "..........", "##########"});
    World w;
    w.grid = &g;
    Body ball = box(0, 100, 8, 8);
    ball.gravity = true;
    ball.bounce = ds::UnitNum::of(I(1));
    w.bodies = {ball};
    ds::Frame f;
    std::vector<double> ys;
    for (int k = 0; k < 200; ++k) {
        f.step(w, frame_opts());
        ys.push_back(w.bodies[0].y.v);
        REQUIRE(w.bodies[0].y.exact);
    }
    for (size_t k = 0; k + 18 < ys.size(); ++k) REQUIRE(ys[k] == ys[k + 18]);
    CHECK(*std::min_element(ys.begin(), ys.end()) == 100);
}

TEST_CASE("a Frame logs sensor pairs as contact pairs, and a sensor never sleeps") {
    World w;
    w.bodies = {sensor(box(0, 0, 10, 10)), solid_box(5, 0, 10, 10)};
    ds::Frame f;
    for (int k = 0; k < 4; ++k) {
        f.step(w, frame_opts());
        const auto pairs = f.contact_pairs();
        REQUIRE(pairs.size() == 1);
        CHECK(pairs[0] == std::pair<uint32_t, uint32_t>{0, 1});
    }
    CHECK_EXACT(w.bodies[1].x, 5);
}

}  // TEST_SUITE
