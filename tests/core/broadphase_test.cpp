// SPDX-License-Identifier: MIT
// The grid pass must be the all-pairs pass, bit for bit: same pairs, same
// order, same values and exactness.
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "contacts.hpp"
#include "detail/ground_index.hpp"
#include "ground.hpp"
#include "tiles.hpp"
#include "support.hpp"

using namespace dst;
using ds::PairMethod;

namespace {

struct Gen {
    std::mt19937_64 rng;
    explicit Gen(uint64_t seed) : rng(seed) {}
    int64_t i(int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); }
    bool chance(int in) { return i(1, in) == 1; }
    Num num(int64_t lo, int64_t hi) {
        if (chance(4)) return F(static_cast<double>(i(lo * 2, hi * 2)) / 2);  // halves, flonum
        return I(static_cast<double>(i(lo, hi)));
    }
};

// A crowd: mostly small boxes packed in a region, a few floors and giants,
// some immovable, some ghosts or not solid, odd sizes and far-away outliers.
std::vector<Body> crowd(Gen& g, int n, int64_t region) {
    std::vector<Body> v;
    for (int k = 0; k < n; ++k) {
        Body b;
        b.x = g.num(0, region);
        b.y = g.num(0, region);
        b.w = g.num(1, 16);
        b.h = g.num(1, 16);
        if (g.chance(30)) b.w = I(0);
        if (g.chance(40)) b.h = I(-static_cast<double>(g.i(1, 8)));
        if (g.chance(25)) b.w = I(static_cast<double>(g.i(100, std::max<int64_t>(100, region))));  // a floor
        if (g.chance(200)) b.w = F(3e18);  // a giant
        if (g.chance(60)) b.x = F(1e15 * (g.chance(2) ? 1 : -1));
        b.solid = !g.chance(8);
        b.immovable = g.chance(6);
        if (g.chance(10)) b.skip = ds::kSkipEntityCollisions;
        b.vx = g.num(-3, 3);
        b.vy = g.num(-3, 3);
        v.push_back(b);
    }
    return v;
}

}  // namespace

TEST_SUITE("broadphase") {

TEST_CASE("the grid pass equals the all-pairs pass on random crowds") {
    int pushed = 0;
    for (uint64_t seed = 1; seed <= 300; ++seed) {
        Gen g(seed);
        const int n = static_cast<int>(g.i(2, seed % 10 == 0 ? 600 : 120));
        std::vector<Body> a = crowd(g, n, g.i(20, 400));
        std::vector<Body> b = a;
        for (int frame = 0; frame < 4; ++frame) {
            const std::vector<Body> before = a;
            ds::resolve_entity_collisions_by(a, PairMethod::AllPairs);
            ds::resolve_entity_collisions_by(b, PairMethod::Grid);
            for (int k = 0; k < n; ++k) {
                INFO("seed " << seed << " frame " << frame << " body " << k);
                REQUIRE(same_body(a[k], b[k]));
                pushed += ds::changed_fields(before[k], a[k]) != 0;
            }
            for (auto* v : {&a, &b})
                for (Body& body : *v) {  // move on, the same way on both sides
                    body.x = body.x + body.vx;
                    body.y = body.y + body.vy;
                }
        }
    }
    CHECK(pushed > 10000);  // the crowds really are crowded
}

TEST_CASE("a pushed body meets partners it did not overlap before the push") {
    // a overlaps b; pushed left by b it comes to overlap c, which lies after b
    // in the list — the all-pairs loop resolves (a, c) next, so must the grid.
    std::vector<Body> v;
    for (int k = 0; k < 60; ++k) v.push_back(solid_box(1000 + 40 * k, 0, 8, 8));  // far, idle
    v[0] = solid_box(20, 0, 10, 10);    // a
    v[1] = solid_box(26, 1, 10, 10);    // b: overlaps a by 4 on x
    v[2] = wall_box(9, 0, 10, 10);      // c: a moves 2 left to 18 — and overlaps c by 1
    std::vector<Body> w = v;
    ds::resolve_entity_collisions_by(v, PairMethod::AllPairs);
    ds::resolve_entity_collisions_by(w, PairMethod::Grid);
    CHECK_EXACT(v[0].x, 19);  // then pushed out of the wall to its right side
    for (size_t k = 0; k < v.size(); ++k) CHECK(same_body(v[k], w[k]));
    CHECK_EXACT(w[0].x, 19);
}

TEST_CASE("indexed ground detection answers as the linear scan does") {
    int grounded = 0, total = 0;
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        Gen g(seed);
        const int n = static_cast<int>(g.i(1, seed % 10 == 0 ? 500 : 100));
        std::vector<Body> scene = crowd(g, n, g.i(20, 300));
        for (size_t k = 0; k < scene.size(); ++k) {
            // stacked on each other: feet near tops, similar speeds
            if (g.chance(2) && k > 0) {
                const Body& below = scene[static_cast<size_t>(g.i(0, static_cast<int64_t>(k) - 1))];
                scene[k].x = below.x + I(static_cast<double>(g.i(-8, 8)));
                scene[k].y = below.y - scene[k].h + I(static_cast<double>(g.i(-5, 5)));
            }
            scene[k].gravity = !g.chance(10);
            scene[k].id = g.chance(5) ? g.i(1, 4) : 0;
        }
        // As a frame does: the colliders become supporters, each body
        // knowing its own slot among them.
        std::vector<ds::Supporter> supporters;
        std::vector<std::ptrdiff_t> slot(scene.size(), -1);
        for (size_t k = 0; k < scene.size(); ++k)
            if (scene[k].collides()) {
                slot[k] = std::ssize(supporters);
                supporters.push_back(ds::Supporter::of(scene[k]));
            }
        ds::SupportIndex index;
        index.build(supporters);
        for (size_t k = 0; k < scene.size(); ++k) {
            Body linear = scene[k], indexed = scene[k];
            linear.on_ground = indexed.on_ground = g.chance(2);
            const bool as_self = !g.chance(3);
            const std::ptrdiff_t self = as_self ? static_cast<std::ptrdiff_t>(k) : -1;
            ds::detect_on_solid(linear, scene, self, nullptr);
            ds::detect_on_supporters(indexed, supporters, index, as_self ? slot[k] : -1, nullptr);
            INFO("seed " << seed << " body " << k);
            REQUIRE(linear.on_ground == indexed.on_ground);
            grounded += linear.on_ground;
            ++total;
        }
    }
    CHECK(grounded > total / 10);  // plenty of bodies really stand on others
}

TEST_CASE("indexed ground detection at the edge of the tolerance, in fractions and far out") {
    // Tops exactly at, just inside and just outside feet ± 4, with feet at
    // fractions a double rounds (0.1 steps) and at large coordinates, where
    // the subtraction itself rounds.
    int grounded = 0, total = 0;
    for (uint64_t seed = 1; seed <= 400; ++seed) {
        Gen g(seed);
        const double base = std::array{0.0, 1e6, 3.3e9, 7.1e12, -2.5e13}[seed % 5];
        std::vector<Body> scene;
        for (int k = 0; k < 60; ++k) {
            Body b;
            b.x = F(base + 0.1 * static_cast<double>(g.i(0, 400)));
            b.y = F(base + 0.1 * static_cast<double>(g.i(0, 400)));
            b.w = F(0.1 * static_cast<double>(g.i(5, 160)));
            b.h = F(0.1 * static_cast<double>(g.i(5, 160)));
            b.vy = F(0.1 * static_cast<double>(g.i(-20, 20)));
            b.solid = b.gravity = true;
            scene.push_back(b);
        }
        for (size_t k = 1; k < scene.size(); k += 2) {  // every other body stands near one before it
            const Body& below = scene[k - 1];
            const double feet = below.y.v - std::array{4.0, -4.0, 3.999999, -3.999999, 4.000001, 0.1}[g.i(0, 5)];
            const double gap = g.chance(2) ? std::nextafter(feet, -1e300) : std::nextafter(feet, 1e300);
            scene[k].y = F((g.chance(2) ? feet : gap) - scene[k].h.v);
            scene[k].x = below.x;
            scene[k].vy = below.vy;
        }
        std::vector<ds::Supporter> supporters;
        for (const Body& b : scene) supporters.push_back(ds::Supporter::of(b));
        ds::SupportIndex index;
        index.build(supporters);
        for (size_t k = 0; k < scene.size(); ++k) {
            Body linear = scene[k], indexed = scene[k];
            const auto self = static_cast<std::ptrdiff_t>(k);
            ds::detect_on_solid(linear, scene, self, nullptr);
            ds::detect_on_supporters(indexed, supporters, index, self, nullptr);
            INFO("seed " << seed << " body " << k);
            REQUIRE(linear.on_ground == indexed.on_ground);
            grounded += linear.on_ground;
            ++total;
        }
    }
    CHECK(grounded > total / 5);
    CHECK(grounded < total);
}

}  // TEST_SUITE
