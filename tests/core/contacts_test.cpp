// SPDX-License-Identifier: MIT
// Entity against entity: aabb_overlap and the sequential push-apart (semantics §4).
#include <vector>

#include "contacts.hpp"
#include "support.hpp"

using namespace dst;

namespace {

std::vector<Body> resolve(std::vector<Body> bodies) {
    ds::resolve_entity_collisions(bodies);
    return bodies;
}

}  // namespace

TEST_SUITE("contacts") {

// ---- aabb_overlap -----------------------------------------------------------

TEST_CASE("aabb_overlap: strict overlap") {
    CHECK(ds::aabb_overlap(0, 0, 16, 16, 8, 8, 16, 16));
    CHECK(ds::aabb_overlap(8, 8, 16, 16, 0, 0, 16, 16));
    CHECK(ds::aabb_overlap(0, 0, 16, 16, 15, 15, 16, 16));
    CHECK(ds::aabb_overlap(0, 0, 100, 100, 10, 10, 5, 5));  // containment
    CHECK_FALSE(ds::aabb_overlap(0, 0, 16, 16, 40, 0, 16, 16));
    CHECK_FALSE(ds::aabb_overlap(0, 0, 16, 16, 0, 40, 16, 16));
}

TEST_CASE("aabb_overlap: touching boxes do not overlap") {
    CHECK_FALSE(ds::aabb_overlap(0, 0, 16, 16, 16, 0, 16, 16));   // right edge
    CHECK_FALSE(ds::aabb_overlap(16, 0, 16, 16, 0, 0, 16, 16));   // left edge
    CHECK_FALSE(ds::aabb_overlap(0, 0, 16, 16, 0, 16, 16, 16));   // bottom edge
    CHECK_FALSE(ds::aabb_overlap(0, 16, 16, 16, 0, 0, 16, 16));   // top edge
    CHECK_FALSE(ds::aabb_overlap(0, 0, 16, 16, 16, 16, 16, 16));  // corner
    CHECK(ds::aabb_overlap(0, 0, 16, 16, 15.5, 0, 16, 16));
}

TEST_CASE("aabb_overlap: zero-size boxes follow the strict formula") {
    // x1 < x2+w2 ∧ x2 < x1+w1 ∧ y1 < y2+h2 ∧ y2 < y1+h1
    CHECK(ds::aabb_overlap(5, 5, 0, 0, 0, 0, 10, 10));        // a point strictly inside
    CHECK_FALSE(ds::aabb_overlap(0, 0, 0, 0, 0, 0, 10, 10));  // on the corner: 0 < 0 fails
    CHECK_FALSE(ds::aabb_overlap(10, 5, 0, 0, 0, 0, 10, 10)); // on the right edge
    CHECK_FALSE(ds::aabb_overlap(5, 5, 0, 0, 5, 5, 0, 0));
}

TEST_CASE("aabb_overlap: negative and huge coordinates") {
    CHECK(ds::aabb_overlap(-20, -20, 16, 16, -8, -8, 16, 16));
    CHECK_FALSE(ds::aabb_overlap(-16, 0, 16, 16, 0, 0, 16, 16));
    CHECK(ds::aabb_overlap(-1, 0, 2, 1, 0, 0, 1, 1));
    CHECK(ds::aabb_overlap(1e9, 0, 16, 16, 1e9 + 15, 0, 16, 16));
    CHECK_FALSE(ds::aabb_overlap(1e9, 0, 16, 16, 1e9 + 16, 0, 16, 16));
    CHECK(ds::aabb_overlap(1e12, 0, 16.5, 16, 1e12 + 16, 0, 16, 16));
}

TEST_CASE("aabb_overlap: the Body overload reads x, y, w, h") {
    CHECK(ds::aabb_overlap(box(0, 0, 16, 16), box(8, 8, 16, 16)));
    CHECK_FALSE(ds::aabb_overlap(box(0, 0, 16, 16), box(16, 0, 16, 16)));
    Body f = box(0, 0, 16, 16);
    f.x = F(15.5);
    CHECK(ds::aabb_overlap(box(0, 0, 16, 16), f));
}

// ---- collision_eligible -----------------------------------------------------

TEST_CASE("collision_eligible: both solid, neither a ghost, overlapping") {
    CHECK(ds::collision_eligible(solid_box(0, 0, 16, 16), solid_box(8, 0, 16, 16)));
    CHECK_FALSE(ds::collision_eligible(box(0, 0, 16, 16), solid_box(8, 0, 16, 16)));
    CHECK_FALSE(ds::collision_eligible(solid_box(0, 0, 16, 16), box(8, 0, 16, 16)));
    CHECK_FALSE(ds::collision_eligible(solid_box(0, 0, 16, 16), solid_box(16, 0, 16, 16)));
    Body ghost = solid_box(8, 0, 16, 16);
    ghost.skip = ds::kSkipEntityCollisions;
    CHECK_FALSE(ds::collision_eligible(solid_box(0, 0, 16, 16), ghost));
    CHECK_FALSE(ds::collision_eligible(ghost, solid_box(0, 0, 16, 16)));
    Body busy = solid_box(8, 0, 16, 16);
    busy.skip = kEverySkip & ~ds::kSkipEntityCollisions;
    CHECK(ds::collision_eligible(solid_box(0, 0, 16, 16), busy));
}

// ---- both movable -----------------------------------------------------------

TEST_CASE("push-apart, both movable: x axis, even overlap split in halves") {
    // ox = 6, oy = 14
    auto r = resolve({solid_box(0, 0, 16, 16), solid_box(10, 2, 16, 16)});
    CHECK_EXACT(r[0].x, -3);
    CHECK_EXACT(r[1].x, 13);
    CHECK_EXACT(r[0].vx, -1);
    CHECK_EXACT(r[1].vx, 1);
    CHECK_EXACT(r[0].y, 0);
    CHECK_EXACT(r[1].y, 2);
    CHECK_EXACT(r[0].vy, 0);
    CHECK_EXACT(r[1].vy, 0);
    CHECK(ds::changed_fields(solid_box(0, 0, 16, 16), r[0]) == (ds::kFieldX | ds::kFieldVx));
    CHECK(ds::changed_fields(solid_box(10, 2, 16, 16), r[1]) == (ds::kFieldX | ds::kFieldVx));
}

TEST_CASE("push-apart, both movable: y axis") {
    // ox = 14, oy = 6
    auto r = resolve({solid_box(0, 0, 16, 16), solid_box(2, 10, 16, 16)});
    CHECK_EXACT(r[0].y, -3);
    CHECK_EXACT(r[1].y, 13);
    CHECK_EXACT(r[0].vy, -1);
    CHECK_EXACT(r[1].vy, 1);
    CHECK_EXACT(r[0].x, 0);
    CHECK_EXACT(r[1].x, 2);
    CHECK_EXACT(r[0].vx, 0);
    CHECK_EXACT(r[1].vx, 0);
}

TEST_CASE("push-apart, both movable: ox == oy resolves on y") {
    auto r = resolve({solid_box(0, 0, 16, 16), solid_box(12, 12, 16, 16)});
    CHECK_EXACT(r[0].y, -2);
    CHECK_EXACT(r[1].y, 14);
    CHECK_EXACT(r[0].vy, -1);
    CHECK_EXACT(r[1].vy, 1);
    CHECK_EXACT(r[0].x, 0);
    CHECK_EXACT(r[1].x, 12);
    CHECK_EXACT(r[0].vx, 0);
    CHECK_EXACT(r[1].vx, 0);
}

TEST_CASE("push-apart, both movable: odd exact overlap, the earlier moves ceil(o/2)") {
    SUBCASE("earlier body moves negative") {
        auto r = resolve({solid_box(0, 0, 16, 16), solid_box(13, 0, 16, 16)});  // o = 3
        CHECK_EXACT(r[0].x, -2);
        CHECK_EXACT(r[1].x, 14);
        CHECK_EXACT(r[0].vx, -1);
        CHECK_EXACT(r[1].vx, 1);
        CHECK_FALSE(ds::aabb_overlap(r[0], r[1]));
    }
    SUBCASE("later body moves negative: the earlier still takes the larger half") {
        auto r = resolve({solid_box(13, 0, 16, 16), solid_box(0, 0, 16, 16)});
        CHECK_EXACT(r[0].x, 15);
        CHECK_EXACT(r[1].x, -1);
        CHECK_EXACT(r[0].vx, 1);
        CHECK_EXACT(r[1].vx, -1);
        CHECK_FALSE(ds::aabb_overlap(r[0], r[1]));
    }
    SUBCASE("on y, o = 5") {
        auto r = resolve({solid_box(0, 11, 16, 16), solid_box(0, 0, 20, 16)});
        // ox = 16, oy = 5; body 1 (cy 8) is above body 0 (cy 19)
        CHECK_EXACT(r[0].y, 14);  // earlier moves ceil(5/2) = 3, positive
        CHECK_EXACT(r[1].y, -2);  // later moves 2, negative
        CHECK_EXACT(r[0].vy, 1);
        CHECK_EXACT(r[1].vy, -1);
    }
    SUBCASE("overlap of 1") {
        auto r = resolve({solid_box(0, 0, 16, 16), solid_box(15, 0, 16, 16)});
        CHECK_EXACT(r[0].x, -1);
        CHECK_EXACT(r[1].x, 15);
        CHECK_EXACT(r[0].vx, -1);
        CHECK_EXACT(r[1].vx, 1);
    }
}

TEST_CASE("push-apart, both movable: any flonum input splits o/2 each as flonums") {
    SUBCASE("flonum position, odd overlap") {
        Body b = solid_box(0, 0, 16, 16);
        b.x = F(13.0);
        auto r = resolve({solid_box(0, 0, 16, 16), b});
        CHECK_FLONUM(r[0].x, -1.5);
        CHECK_FLONUM(r[1].x, 14.5);
        CHECK_EXACT(r[0].vx, -1);
        CHECK_EXACT(r[1].vx, 1);
    }
    SUBCASE("flonum position, even overlap: still flonums") {
        Body b = solid_box(0, 0, 16, 16);
        b.x = F(12.0);
        auto r = resolve({solid_box(0, 0, 16, 16), b});
        CHECK_FLONUM(r[0].x, -2);
        CHECK_FLONUM(r[1].x, 14);
    }
    SUBCASE("flonum size on the axis") {
        Body a = solid_box(0, 0, 16, 16);
        a.w = F(16);
        auto r = resolve({a, solid_box(13, 0, 16, 16)});
        CHECK_FLONUM(r[0].x, -1.5);
        CHECK_FLONUM(r[1].x, 14.5);
    }
    SUBCASE("flonums on the other axis do not matter") {
        Body a = solid_box(0, 0, 16, 16);
        a.y = F(0.5);
        a.h = F(16);
        auto r = resolve({a, solid_box(13, 0, 16, 16)});  // ox = 3, oy = 15.5
        CHECK_EXACT(r[0].x, -2);
        CHECK_EXACT(r[1].x, 14);
        CHECK_FLONUM(r[0].y, 0.5);
    }
    SUBCASE("fractional overlap") {
        Body b = solid_box(0, 0, 16, 16);
        b.x = F(15.5);
        auto r = resolve({solid_box(0, 0, 16, 16), b});
        CHECK_FLONUM(r[0].x, -0.25);
        CHECK_FLONUM(r[1].x, 15.75);
    }
}

TEST_CASE("push-apart, both movable: equal centres, the earlier moves negative") {
    SUBCASE("identical boxes: ox == oy, axis y") {
        auto r = resolve({solid_box(0, 0, 16, 16), solid_box(0, 0, 16, 16)});
        CHECK_EXACT(r[0].y, -8);
        CHECK_EXACT(r[1].y, 8);
        CHECK_EXACT(r[0].vy, -1);
        CHECK_EXACT(r[1].vy, 1);
        CHECK_EXACT(r[0].x, 0);
        CHECK_EXACT(r[1].x, 0);
    }
    SUBCASE("x axis tie, wide body first") {
        // ox = 8, oy = 16; both centres at x = 8
        auto r = resolve({solid_box(0, 0, 16, 16), solid_box(4, 0, 8, 16)});
        CHECK_EXACT(r[0].x, -4);
        CHECK_EXACT(r[1].x, 8);
        CHECK_EXACT(r[0].vx, -1);
        CHECK_EXACT(r[1].vx, 1);
    }
    SUBCASE("x axis tie, narrow body first") {
        auto r = resolve({solid_box(4, 0, 8, 16), solid_box(0, 0, 16, 16)});
        CHECK_EXACT(r[0].x, 0);
        CHECK_EXACT(r[1].x, 4);
        CHECK_EXACT(r[0].vx, -1);
        CHECK_EXACT(r[1].vx, 1);
    }
    SUBCASE("y axis tie with an odd overlap") {
        // [1, 14) and [0, 15): both centres at y = 7.5; oy = 13 < ox = 16
        auto r = resolve({solid_box(0, 1, 16, 13), solid_box(0, 0, 16, 15)});
        CHECK_EXACT(r[0].y, -6);  // the earlier moves ceil(13/2) = 7 up
        CHECK_EXACT(r[1].y, 6);   // the later moves 6 down
        CHECK_EXACT(r[0].vy, -1);
        CHECK_EXACT(r[1].vy, 1);
    }
}

// ---- movable against immovable ----------------------------------------------

TEST_CASE("immovable vs movable: landing on top") {
    // m's centre (y 18) is above s's centre (y 24)
    auto r = resolve({wall_box(0, 16, 64, 16), solid_box(10, 10, 16, 16)});
    CHECK(same_body(r[0], wall_box(0, 16, 64, 16)));
    CHECK_EXACT(r[1].y, 0);  // s.y - m.h
    CHECK_EXACT(r[1].vy, 0);
    CHECK_EXACT(r[1].x, 10);
    CHECK_EXACT(r[1].vx, 0);
}

TEST_CASE("immovable vs movable: the mover is only displaced, order does not matter") {
    Body m = solid_box(10, 10, 16, 16);
    m.vx = I(3);
    m.vy = I(7);
    auto r = resolve({m, wall_box(0, 16, 64, 16)});
    CHECK_EXACT(r[0].y, 0);
    CHECK_EXACT(r[0].vy, 0);
    CHECK_EXACT(r[0].x, 10);
    CHECK_EXACT(r[0].vx, 3);  // the other axis keeps its velocity
    CHECK(same_body(r[1], wall_box(0, 16, 64, 16)));
    CHECK(ds::changed_fields(m, r[0]) == (ds::kFieldY | ds::kFieldVy));
}

TEST_CASE("immovable vs movable: centre above wins over a narrower x overlap") {
    // m = [-14, 2) × [4, 20) over the left corner of s = [0, 64) × [16, 32):
    // ox = 2 < oy = 4, but m's centre (12) is above s's (24): m lands, no side push
    Body m = solid_box(-14, 4, 16, 16);
    m.vx = I(2);
    m.vy = I(5);
    auto r = resolve({m, wall_box(0, 16, 64, 16)});
    CHECK_EXACT(r[0].y, 0);
    CHECK_EXACT(r[0].vy, 0);
    CHECK_EXACT(r[0].x, -14);
    CHECK_EXACT(r[0].vx, 2);
}

TEST_CASE("immovable vs movable: side push when the centre is not above") {
    SUBCASE("from the left") {
        // wall s = [0, 16) × [0, 64); m = [-12, 4) × [30, 46): cy 38 > 32, ox 4 < oy 16
        Body m = solid_box(-12, 30, 16, 16);
        m.vx = I(4);
        m.vy = I(1);
        auto r = resolve({wall_box(0, 0, 16, 64), m});
        CHECK_EXACT(r[1].x, -16);  // s.x - m.w
        CHECK_EXACT(r[1].vx, 0);
        CHECK_EXACT(r[1].y, 30);
        CHECK_EXACT(r[1].vy, 1);
    }
    SUBCASE("from the right") {
        Body m = solid_box(12, 30, 16, 16);
        m.vx = I(-4);
        auto r = resolve({wall_box(0, 0, 16, 64), m});
        CHECK_EXACT(r[1].x, 16);  // s.x + s.w
        CHECK_EXACT(r[1].vx, 0);
        CHECK_EXACT(r[1].y, 30);
    }
    SUBCASE("equal centres on y are not 'above'") {
        auto r = resolve({wall_box(0, 0, 16, 16), solid_box(12, 0, 16, 16)});
        CHECK_EXACT(r[1].x, 16);
        CHECK_EXACT(r[1].vx, 0);
        CHECK_EXACT(r[1].y, 0);
    }
    SUBCASE("equal centres on both axes: ox == oy, so pushed below") {
        auto r = resolve({wall_box(0, 0, 16, 16), solid_box(0, 0, 16, 16)});
        CHECK_EXACT(r[1].y, 16);  // s.y + s.h
        CHECK_EXACT(r[1].vy, 0);
        CHECK_EXACT(r[1].x, 0);
    }
    SUBCASE("equal centres on x, side push goes right") {
        // s = [0, 16) × [0, 64); m = [4, 12) × [40, 56): cy 48 > 32; ox 8 < oy 16
        auto r = resolve({wall_box(0, 0, 16, 64), solid_box(4, 40, 8, 16)});
        CHECK_EXACT(r[1].x, 16);
        CHECK_EXACT(r[1].vx, 0);
    }
}

TEST_CASE("immovable vs movable: pushed below when the centre is below and oy <= ox") {
    // s = [0, 64) × [0, 16); m = [10, 26) × [12, 28): cy 20 > 8, ox 16, oy 4
    Body m = solid_box(10, 12, 16, 16);
    m.vy = I(-6);
    auto r = resolve({wall_box(0, 0, 64, 16), m});
    CHECK_EXACT(r[1].y, 16);
    CHECK_EXACT(r[1].vy, 0);
    CHECK_EXACT(r[1].x, 10);
}

TEST_CASE("immovable vs movable: exactness of the snap") {
    SUBCASE("flonum s.y") {
        Body s = wall_box(0, 16, 64, 16);
        s.y = F(16);
        auto r = resolve({s, solid_box(10, 10, 16, 16)});
        CHECK_FLONUM(r[1].y, 0);
        CHECK_EXACT(r[1].vy, 0);
    }
    SUBCASE("flonum m.h") {
        Body m = solid_box(10, 10, 16, 16);
        m.h = F(16);
        auto r = resolve({wall_box(0, 16, 64, 16), m});
        CHECK_FLONUM(r[1].y, 0);
        CHECK_EXACT(r[1].vy, 0);
    }
    SUBCASE("flonum m.y alone: the snap is computed from s.y and m.h only") {
        Body m = solid_box(10, 10, 16, 16);
        m.y = F(10.5);
        auto r = resolve({wall_box(0, 16, 64, 16), m});
        CHECK_EXACT(r[1].y, 0);
        CHECK_EXACT(r[1].vy, 0);
    }
    SUBCASE("flonum velocity becomes exact 0") {
        Body m = solid_box(10, 10, 16, 16);
        m.vy = F(3.5);
        auto r = resolve({wall_box(0, 16, 64, 16), m});
        CHECK_EXACT(r[1].vy, 0);
    }
    SUBCASE("side push from flonum s.x") {
        Body s = wall_box(0, 0, 16, 64);
        s.x = F(0);
        auto r = resolve({s, solid_box(-12, 30, 16, 16)});
        CHECK_FLONUM(r[1].x, -16);
        CHECK_EXACT(r[1].vx, 0);
    }
}

// ---- pairs that are skipped -------------------------------------------------

TEST_CASE("both immovable: skipped") {
    const std::vector<Body> in = {wall_box(0, 0, 16, 16), wall_box(8, 4, 16, 16)};
    auto r = resolve(in);
    CHECK(same_body(r[0], in[0]));
    CHECK(same_body(r[1], in[1]));
}

TEST_CASE("not solid, ghosts and touching boxes are left alone") {
    SUBCASE("one not solid") {
        const std::vector<Body> in = {solid_box(0, 0, 16, 16), box(8, 0, 16, 16)};
        auto r = resolve(in);
        CHECK(same_body(r[0], in[0]));
        CHECK(same_body(r[1], in[1]));
    }
    SUBCASE("one skips entity-collisions") {
        Body ghost = solid_box(8, 0, 16, 16);
        ghost.skip = ds::kSkipEntityCollisions;
        const std::vector<Body> in = {solid_box(0, 0, 16, 16), ghost};
        auto r = resolve(in);
        CHECK(same_body(r[0], in[0]));
        CHECK(same_body(r[1], in[1]));
        const std::vector<Body> rev = {ghost, wall_box(0, 0, 16, 16)};
        auto r2 = resolve(rev);
        CHECK(same_body(r2[0], rev[0]));
        CHECK(same_body(r2[1], rev[1]));
    }
    SUBCASE("touching") {
        const std::vector<Body> in = {solid_box(0, 0, 16, 16), solid_box(16, 0, 16, 16),
                                      solid_box(0, 16, 16, 16)};
        auto r = resolve(in);
        for (size_t i = 0; i < in.size(); ++i) CHECK(same_body(r[i], in[i]));
    }
    SUBCASE("other skip bits do not make a ghost") {
        Body b = solid_box(13, 0, 16, 16);
        b.skip = kEverySkip & ~ds::kSkipEntityCollisions;
        auto r = resolve({solid_box(0, 0, 16, 16), b});
        CHECK_EXACT(r[0].x, -2);
        CHECK_EXACT(r[1].x, 14);
    }
    SUBCASE("empty and single lists") {
        std::vector<Body> none;
        ds::resolve_entity_collisions(none);
        CHECK(none.empty());
        auto one = resolve({solid_box(0, 0, 16, 16)});
        CHECK(same_body(one[0], solid_box(0, 0, 16, 16)));
    }
}

// ---- pair order -------------------------------------------------------------

TEST_CASE("resolve_pair pushes one pair apart; a is the earlier") {
    Body a = solid_box(13, 0, 16, 16);
    Body b = solid_box(0, 0, 16, 16);
    ds::resolve_pair(a, b);
    CHECK_EXACT(a.x, 15);
    CHECK_EXACT(b.x, -1);
    CHECK_EXACT(a.vx, 1);
    CHECK_EXACT(b.vx, -1);
}

TEST_CASE("resolve_pair with an immovable body, either side; both immovable is a no-op") {
    Body s = wall_box(0, 16, 64, 16);
    Body m = solid_box(10, 10, 16, 16);
    ds::resolve_pair(s, m);
    CHECK(same_body(s, wall_box(0, 16, 64, 16)));
    CHECK_EXACT(m.y, 0);
    CHECK_EXACT(m.vy, 0);
    Body m2 = solid_box(10, 10, 16, 16);
    Body s2 = wall_box(0, 16, 64, 16);
    ds::resolve_pair(m2, s2);
    CHECK_EXACT(m2.y, 0);
    CHECK(same_body(s2, wall_box(0, 16, 64, 16)));
    Body a = wall_box(0, 0, 16, 16), b = wall_box(8, 8, 16, 16);
    ds::resolve_pair(a, b);
    CHECK(same_body(a, wall_box(0, 0, 16, 16)));
    CHECK(same_body(b, wall_box(8, 8, 16, 16)));
}

TEST_CASE("sequential pass: each pair sees what earlier pairs produced") {
    // A [0,16), B [12,28), C [24,40) in a row.
    // (A,B): ox 4 → A.x -2, B.x 14. (A,C): apart. (B,C): B [14,30) vs C [24,40),
    // ox 6 (not the original 4) → B.x 11, C.x 27.
    auto r = resolve({solid_box(0, 0, 16, 16), solid_box(12, 0, 16, 16),
                      solid_box(24, 0, 16, 16)});
    CHECK_EXACT(r[0].x, -2);
    CHECK_EXACT(r[1].x, 11);
    CHECK_EXACT(r[2].x, 27);
    CHECK_EXACT(r[0].vx, -1);
    CHECK_EXACT(r[1].vx, -1);
    CHECK_EXACT(r[2].vx, 1);
    // one pass only: A and B overlap again afterwards
    CHECK(ds::aabb_overlap(r[0], r[1]));
}

TEST_CASE("sequential pass: pair (0, 2) sees the result of pair (0, 1)") {
    // A [0,16), B [10,26), C [-10,6).
    // (A,B): ox 6, A moves -3 → A [-3,13), B [13,29).
    // (A,C): ox 9, C's centre is smaller → C moves negative 4, A (earlier) +5 → A.x 2, C.x -14.
    // (B,C): apart.
    auto r = resolve({solid_box(0, 0, 16, 16), solid_box(10, 0, 16, 16),
                      solid_box(-10, 0, 16, 16)});
    CHECK_EXACT(r[0].x, 2);
    CHECK_EXACT(r[1].x, 13);
    CHECK_EXACT(r[2].x, -14);
    CHECK_EXACT(r[0].vx, 1);
    CHECK_EXACT(r[1].vx, 1);
    CHECK_EXACT(r[2].vx, -1);
}

TEST_CASE("sequential pass: a pair separated by an earlier pair is not resolved") {
    // A [0,16), B [-10,6), C [-14,2): A and C overlap at the start.
    // (A,B): ox 6, B's centre is smaller → A +3 → [3,19), B -3 → [-13,3).
    // (A,C): A [3,19) vs C [-14,2): apart now, skipped.
    // (B,C): ox 15, C's centre (-6) < B's (-5) → B +8 (ceil 7.5), C -7.
    auto r = resolve({solid_box(0, 0, 16, 16), solid_box(-10, 0, 16, 16),
                      solid_box(-14, 0, 16, 16)});
    CHECK_EXACT(r[0].x, 3);
    CHECK_EXACT(r[1].x, -5);
    CHECK_EXACT(r[2].x, -21);
    CHECK_EXACT(r[0].vx, 1);
    CHECK_EXACT(r[1].vx, 1);
    CHECK_EXACT(r[2].vx, -1);
}

TEST_CASE("sequential pass: the list order changes the outcome") {
    // the same three boxes as above, C first: (C,A) ox 6 → C.x -13, A.x 3;
    // (C,B) apart ([-13,3) vs [10,26)); (A,B) A [3,19) vs B [10,26), ox 9 → A.x -2, B.x 14.
    auto r = resolve({solid_box(-10, 0, 16, 16), solid_box(0, 0, 16, 16),
                      solid_box(10, 0, 16, 16)});
    CHECK_EXACT(r[0].x, -13);
    CHECK_EXACT(r[1].x, -2);
    CHECK_EXACT(r[2].x, 14);
    CHECK_EXACT(r[0].vx, -1);
    CHECK_EXACT(r[1].vx, -1);
    CHECK_EXACT(r[2].vx, 1);
}

TEST_CASE("sequential pass: a box on a platform and a box beside it") {
    // platform P immovable [0,64) × [32,48); box A [0,16) × [20,36) lands on P;
    // box B [14,30) × [16,32) then meets the landed A: A [0,16) × [16,32) vs B, ox 2 → x.
    auto r = resolve({wall_box(0, 32, 64, 16), solid_box(0, 20, 16, 16),
                      solid_box(14, 16, 16, 16)});
    // (P,A): A lands: y 16, vy 0. (P,B): B [16,32) touches P's top: no overlap.
    // (A,B): ox 2, oy 16 → A.x -1, B.x 15, vx -1 / +1.
    CHECK_EXACT(r[1].y, 16);
    CHECK_EXACT(r[1].vy, 0);
    CHECK_EXACT(r[1].x, -1);
    CHECK_EXACT(r[1].vx, -1);
    CHECK_EXACT(r[2].x, 15);
    CHECK_EXACT(r[2].vx, 1);
    CHECK_EXACT(r[2].y, 16);
    CHECK(same_body(r[0], wall_box(0, 32, 64, 16)));
}

TEST_CASE("push-apart keeps every other field") {
    Body a = solid_box(0, 0, 16, 16);
    a.ay = I(-15);
    a.gravity = true;
    a.on_ground = true;
    a.id = 3;
    a.group = 4;
    a.local_x = F(1.5);
    Body b = solid_box(13, 0, 16, 16);
    auto r = resolve({a, b});
    CHECK(ds::changed_fields(a, r[0]) == (ds::kFieldX | ds::kFieldVx));
    CHECK(r[0].on_ground);
    CHECK(r[0].gravity);
    CHECK(r[0].id == 3);
    CHECK(r[0].group == 4);
    CHECK(ds::same(r[0].ay, I(-15)));
    CHECK(ds::same(r[0].local_x, F(1.5)));
}

}  // TEST_SUITE
