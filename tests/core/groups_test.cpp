// SPDX-License-Identifier: MIT
// Rigid groups: members follow the first origin of their group (semantics §4).
#include <vector>

#include "groups.hpp"
#include "support.hpp"

using namespace dst;

namespace {

Body origin(int64_t group, double x, double y) {
    Body b = box(x, y, 16, 16);
    b.group = group;
    b.group_origin = true;
    return b;
}

Body member(int64_t group, double lx, double ly, double x = 0, double y = 0) {
    Body b = box(x, y, 8, 8);
    b.group = group;
    b.local_x = I(lx);
    b.local_y = I(ly);
    return b;
}

std::vector<Body> sync(std::vector<Body> bodies) {
    ds::sync_groups(bodies);
    return bodies;
}

}  // namespace

TEST_SUITE("groups") {

TEST_CASE("members are placed at origin + local offset") {
    auto r = sync({origin(1, 100, 50), member(1, 10, -5), member(1, -20, 30, 999, 999)});
    CHECK_EXACT(r[1].x, 110);
    CHECK_EXACT(r[1].y, 45);
    CHECK_EXACT(r[2].x, 80);
    CHECK_EXACT(r[2].y, 80);
    CHECK(same_body(r[0], origin(1, 100, 50)));
}

TEST_CASE("only x and y of a member change") {
    Body m = member(1, 10, -5);
    m.vx = I(3);
    m.vy = F(1.5);
    m.solid = true;
    auto r = sync({origin(1, 100, 50), m});
    CHECK(ds::changed_fields(m, r[1]) == (ds::kFieldX | ds::kFieldY));
    CHECK(ds::same(r[1].vx, I(3)));
    CHECK(ds::same(r[1].vy, F(1.5)));
    CHECK(ds::same(r[1].local_x, I(10)));
    CHECK(ds::same(r[1].w, I(8)));
}

TEST_CASE("a member already in place is unchanged") {
    const Body m = member(1, 10, -5, 110, 45);
    auto r = sync({origin(1, 100, 50), m});
    CHECK(same_body(r[1], m));
}

TEST_CASE("a member listed before its origin still follows it") {
    auto r = sync({member(2, 4, 4), origin(2, -30, -40)});
    CHECK_EXACT(r[0].x, -26);
    CHECK_EXACT(r[0].y, -36);
}

TEST_CASE("the first origin in list order wins; later origins are members") {
    Body late = origin(1, 500, 500);
    late.local_x = I(1);
    late.local_y = I(2);
    auto r = sync({member(1, 10, 10), origin(1, 100, 50), late});
    CHECK_EXACT(r[0].x, 110);
    CHECK_EXACT(r[0].y, 60);
    CHECK(same_body(r[1], origin(1, 100, 50)));
    CHECK_EXACT(r[2].x, 101);
    CHECK_EXACT(r[2].y, 52);
    CHECK(r[2].group_origin);
}

TEST_CASE("a group without an origin is left alone") {
    const std::vector<Body> in = {member(3, 10, 10, 1, 2), member(3, 0, 0, 7, 8),
                                  origin(4, 100, 100)};
    auto r = sync(in);
    CHECK(same_body(r[0], in[0]));
    CHECK(same_body(r[1], in[1]));
    CHECK(same_body(r[2], in[2]));
}

TEST_CASE("group 0 means no group, even with group_origin set") {
    Body fake = origin(0, 100, 100);
    const std::vector<Body> in = {fake, member(0, 5, 5, 1, 2), box(3, 4, 16, 16)};
    auto r = sync(in);
    for (size_t i = 0; i < in.size(); ++i) CHECK(same_body(r[i], in[i]));
}

TEST_CASE("groups are independent") {
    auto r = sync({origin(1, 0, 0), origin(2, 1000, 2000), member(2, 1, 1), member(1, 2, 2)});
    CHECK_EXACT(r[2].x, 1001);
    CHECK_EXACT(r[2].y, 2001);
    CHECK_EXACT(r[3].x, 2);
    CHECK_EXACT(r[3].y, 2);
}

TEST_CASE("exactness: x = origin.x + local_x is exact iff both are") {
    SUBCASE("flonum origin x") {
        Body o = origin(1, 100, 50);
        o.x = F(100.5);
        auto r = sync({o, member(1, 10, -5)});
        CHECK_FLONUM(r[1].x, 110.5);
        CHECK_EXACT(r[1].y, 45);
    }
    SUBCASE("flonum local y") {
        Body m = member(1, 10, -5);
        m.local_y = F(-5.0);
        auto r = sync({origin(1, 100, 50), m});
        CHECK_EXACT(r[1].x, 110);
        CHECK_FLONUM(r[1].y, 45);
    }
    SUBCASE("a flonum member position does not matter: it is overwritten") {
        Body m = member(1, 10, -5);
        m.x = F(3.25);
        auto r = sync({origin(1, 100, 50), m});
        CHECK_EXACT(r[1].x, 110);
    }
    SUBCASE("an exact member at the right value but flonum sum becomes flonum") {
        Body o = origin(1, 100, 50);
        o.y = F(50);
        const Body m = member(1, 10, -5, 110, 45);
        auto r = sync({o, m});
        CHECK_EXACT(r[1].x, 110);
        CHECK_FLONUM(r[1].y, 45);
        CHECK(ds::changed_fields(m, r[1]) == ds::kFieldY);
    }
}

TEST_CASE("huge and negative coordinates") {
    auto r = sync({origin(9, 1e9, -1e9), member(9, -1, 1)});
    CHECK_EXACT(r[1].x, 999999999.0);
    CHECK_EXACT(r[1].y, -999999999.0);
}

TEST_CASE("groups ignore skip bits and solidity") {
    Body m = member(1, 10, -5);
    m.skip = kEverySkip;
    auto r = sync({origin(1, 100, 50), m});
    CHECK_EXACT(r[1].x, 110);
    CHECK_EXACT(r[1].y, 45);
}

TEST_CASE("an empty list") {
    std::vector<Body> none;
    ds::sync_groups(none);
    CHECK(none.empty());
}

}  // TEST_SUITE
