// SPDX-License-Identifier: MIT
// Drawing between two steps: each view moved α of the way from its match in
// the step before, teleports and newcomers drawn where they are.
#include <doctest/doctest.h>

#include <vector>

#include "interpolate.hpp"

using namespace ds::render;

namespace {

EntityView at(double x, double y, double w = 8, double h = 8) {
    EntityView v;
    v.x = x, v.y = y, v.w = w, v.h = h;
    return v;
}

}  // namespace

TEST_SUITE("interpolate") {

TEST_CASE("each body is drawn α of the way from the step before") {
    std::vector<EntityView> now = {at(10, 20), at(100, 0)};
    const std::vector<EntityView> before = {at(6, 24), at(100, 8)};
    const std::vector<int64_t> ids = {0, 0};
    interpolate_views(now, ids, before, ids, 0.25);
    CHECK(now[0].x == 7);   // 6 + 0.25 · 4
    CHECK(now[0].y == 23);  // 24 − 0.25 · 4
    CHECK(now[1].y == 6);
    std::vector<EntityView> same = {at(10, 20)};
    interpolate_views(same, std::vector<int64_t>{0}, before, std::vector<int64_t>{0}, 0);
    CHECK(same[0].x == 6);  // α 0: where the step before left it
}

TEST_CASE("a teleport, a newcomer and a different body are drawn where they are") {
    std::vector<EntityView> now = {at(500, 20), at(10, 10), at(30, 30, 16, 16)};
    const std::vector<EntityView> before = {at(6, 20), at(8, 10)};
    interpolate_views(now, std::vector<int64_t>{0, 0, 0}, before, std::vector<int64_t>{0, 0}, 0.5);
    CHECK(now[0].x == 500);  // moved 494 px: a teleport
    CHECK(now[1].x == 9);
    CHECK(now[2].x == 30);   // nobody there before
    std::vector<EntityView> resized = {at(10, 10, 16, 16)};
    interpolate_views(resized, std::vector<int64_t>{0}, before, std::vector<int64_t>{0}, 0.5);
    CHECK(resized[0].x == 10);  // another size: another body
}

TEST_CASE("a body with an id is found where it was, though the list changed") {
    std::vector<EntityView> now = {at(20, 0), at(40, 0)};
    const std::vector<EntityView> before = {at(0, 0), at(30, 0), at(16, 0)};
    const std::vector<int64_t> now_ids = {7, 9}, before_ids = {5, 9, 7};
    interpolate_views(now, now_ids, before, before_ids, 0.5);
    CHECK(now[0].x == 18);  // id 7 was at 16
    CHECK(now[1].x == 35);  // id 9 was at 30, in the same place in the list
}

TEST_CASE("the camera too, unless it jumped") {
    CHECK(interpolated(100, 104, 0.5) == 102);
    CHECK(interpolated(0, 1000, 0.5) == 1000);
}

}  // TEST_SUITE
