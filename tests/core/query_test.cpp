// SPDX-License-Identifier: MIT
// Spatial queries against brute force: every grid answer equals the plain
// loop over all boxes (or all cells), in the same order.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "contacts.hpp"
#include "query.hpp"

using ds::Box;
using ds::RayHit;
using ds::Segment;
using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

namespace {

std::vector<Box> random_boxes(std::mt19937& rng, size_t n, double span, double size) {
    std::uniform_real_distribution<double> pos(0, span), len(1, size);
    std::uniform_int_distribution<int> whole(0, 3);
    std::vector<Box> out(n);
    for (Box& b : out) {
        b = {pos(rng), pos(rng), len(rng), len(rng)};
        if (whole(rng) == 0) b = {std::floor(b.x), std::floor(b.y), std::floor(b.w), std::floor(b.h)};
    }
    return out;
}

Pairs brute_pairs(const std::vector<Box>& a, const std::vector<Box>& b) {
    Pairs out;
    for (uint32_t i = 0; i < a.size(); ++i)
        for (uint32_t j = 0; j < b.size(); ++j)
            if (ds::aabb_overlap(a[i].x, a[i].y, a[i].w, a[i].h, b[j].x, b[j].y, b[j].w, b[j].h))
                out.emplace_back(i, j);
    return out;
}

// The cells a segment enters, by trying every cell as a box.
std::vector<RayHit> brute_cells(const ds::TileGrid& g, const Segment& s) {
    std::vector<Box> cells;
    std::vector<std::pair<int64_t, int64_t>> where;
    for (int64_t r = g.origin_row(); r < g.origin_row() + g.rows(); ++r)
        for (int64_t c = g.origin_col(); c < g.origin_col() + g.cols(); ++c)
            if (g.solid(c, r)) {
                cells.push_back({double(c) * g.tile_width(), double(r) * g.tile_height(),
                                 double(g.tile_width()), double(g.tile_height())});
                where.emplace_back(c, r);
            }
    std::vector<RayHit> hits;
    ds::raycast_boxes(cells, s, hits);
    for (RayHit& h : hits) {
        h.col = where[static_cast<size_t>(h.body)].first;
        h.row = where[static_cast<size_t>(h.body)].second;
        h.body = -1;
    }
    ds::sort_hits(hits);
    return hits;
}

void check_same(const std::vector<RayHit>& got, const std::vector<RayHit>& want) {
    REQUIRE(got.size() == want.size());
    for (size_t k = 0; k < got.size(); ++k) {
        CHECK(got[k].t == want[k].t);
        CHECK(got[k].x == want[k].x);
        CHECK(got[k].y == want[k].y);
        CHECK(got[k].nx == want[k].nx);
        CHECK(got[k].ny == want[k].ny);
        CHECK(got[k].col == want[k].col);
        CHECK(got[k].row == want[k].row);
    }
}

}  // namespace

TEST_SUITE("query") {
    TEST_CASE("rectangles and points use strict overlap and half-open boxes") {
        const std::vector<Box> boxes = {{0, 0, 16, 16}, {16, 0, 16, 16}, {8, 8, 4, 4}};
        std::vector<uint32_t> out;
        ds::query_rect(boxes, {16, 0, 1, 1}, out);  // touching box 0's right edge only
        CHECK(out == std::vector<uint32_t>{1});
        out.clear();
        ds::query_point(boxes, 16, 8, out);  // x = 16 is box 1's, not box 0's
        CHECK(out == std::vector<uint32_t>{1});
        out.clear();
        ds::query_point(boxes, 9, 9, out);
        CHECK(out == std::vector<uint32_t>{0, 2});
    }

    TEST_CASE("pairs equal the brute-force loop, in order, for random scenes") {
        std::mt19937 rng(7);
        ds::PairQueryScratch scratch;
        for (int round = 0; round < 40; ++round) {
            const auto a = random_boxes(rng, 1 + rng() % 300, 400, round % 5 == 0 ? 200 : 20);
            const auto b = random_boxes(rng, 1 + rng() % 300, 400, 20);
            Pairs got;
            ds::overlapping_pairs(a, b, {}, scratch, got);
            CHECK(got == brute_pairs(a, b));
        }
    }

    TEST_CASE("a box never pairs with itself and a shared pair is reported once") {
        // a = {p, q, r}, b = {q, p}: p and q are in both sets.
        const Box p{0, 0, 10, 10}, q{5, 5, 10, 10}, r{8, 0, 4, 4};
        const std::vector<Box> a = {p, q, r}, b = {q, p};
        const std::vector<int32_t> a_in_b = {1, 0, -1}, b_in_a = {1, 0};
        ds::PairQueryScratch scratch;
        Pairs got;
        ds::overlapping_pairs(a, b, {a_in_b, b_in_a}, scratch, got);
        // (p, q) once, from p (not again as (q, p)); r meets p only.
        CHECK(got == Pairs{{0, 0}, {2, 1}});
    }

    TEST_CASE("a ray stops at the first solid cell, on its edge") {
        // Row 1 of a 6 × 3 grid of 16 px: a wall at column 4.
        std::vector<uint8_t> solid(18, 0);
        solid[1 * 6 + 4] = 1;
        const ds::TileGrid g(6, 3, 16, 16, solid);
        std::vector<RayHit> hits;
        ds::raycast_cells(g, {8, 20, 90, 20}, true, hits);
        REQUIRE(hits.size() == 1);
        CHECK(hits[0].x == 64);
        CHECK(hits[0].y == 20);
        CHECK(hits[0].nx == -1);
        CHECK(hits[0].ny == 0);
        CHECK(hits[0].col == 4);
        CHECK(hits[0].row == 1);
        CHECK(hits[0].t == doctest::Approx(56.0 / 82.0));
        hits.clear();
        ds::raycast_cells(g, {8, 20, 64, 20}, true, hits);  // the end itself is not included
        CHECK(hits.empty());
        ds::raycast_cells(g, {70, 20, 0, 20}, true, hits);  // starting inside the wall
        CHECK(hits.empty());
    }

    TEST_CASE("cell casts equal trying every cell, for random grids and segments") {
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> coord(-40, 360);
        for (int round = 0; round < 60; ++round) {
            const int cols = 1 + static_cast<int>(rng() % 20), rows = 1 + static_cast<int>(rng() % 20);
            const int tw = 8 << (rng() % 2), th = 8 << (rng() % 2);
            std::vector<uint8_t> solid(static_cast<size_t>(cols * rows));
            for (auto& c : solid) c = rng() % 4 == 0;
            const ds::TileGrid g(cols, rows, tw, th, solid, round % 3 - 1, round % 2);
            for (int k = 0; k < 50; ++k) {
                Segment s{coord(rng), coord(rng), coord(rng), coord(rng)};
                if (k % 5 == 0) s = {std::floor(s.x0 / 8) * 8, std::floor(s.y0), std::floor(s.x1), std::floor(s.y0)};
                if (k % 7 == 0) s.x1 = s.x0;
                std::vector<RayHit> all;
                ds::raycast_cells(g, s, false, all);
                check_same(all, brute_cells(g, s));
                std::vector<RayHit> first;
                ds::raycast_cells(g, s, true, first);
                CHECK(first.size() == (all.empty() ? 0u : 1u));
            }
        }
    }

    TEST_CASE("box casts: entry face, corners, boxes holding the start") {
        const std::vector<Box> boxes = {{20, 0, 10, 10}, {0, 0, 5, 5}, {40, 40, 10, 10}};
        std::vector<RayHit> hits;
        ds::raycast_boxes(boxes, {2, 2, 100, 2}, hits);  // from inside box 1
        REQUIRE(hits.size() == 1);
        CHECK(hits[0].body == 0);
        CHECK(hits[0].x == 20);
        CHECK(hits[0].nx == -1);
        hits.clear();
        ds::raycast_boxes(boxes, {30, 30, 60, 60}, hits);  // through box 2's corner
        REQUIRE(hits.size() == 1);
        CHECK(hits[0].x == 40);
        CHECK(hits[0].y == 40);
        CHECK(hits[0].nx == -1);
        CHECK(hits[0].ny == -1);
    }
}
