// SPDX-License-Identifier: MIT
// The motion steps, skip bits and changed_fields (semantics §1, §3, §4).
#include <cmath>
#include <cstring>

#include "body.hpp"
#include "steps.hpp"
#include "support.hpp"

using namespace dst;

namespace {

Body faller(double vy, double ay) {
    Body b = box(0, 0, 16, 16);
    b.gravity = true;
    b.vy = I(vy);
    b.ay = I(ay);
    return b;
}

}  // namespace

TEST_SUITE("steps") {

TEST_CASE("the exported constants") {
    CHECK(ds::kGravity == 1.0);
    CHECK(ds::kJumpForce == 15.0);
    CHECK(ds::kOnSolidTolerance == 4.0);
}

// ---- skip names -------------------------------------------------------------

TEST_CASE("skip_bit / skip_name map the seed's nine symbols") {
    CHECK(ds::skip_bit("acceleration") == ds::kSkipAcceleration);
    CHECK(ds::skip_bit("gravity") == ds::kSkipGravity);
    CHECK(ds::skip_bit("velocity-x") == ds::kSkipVelocityX);
    CHECK(ds::skip_bit("velocity-y") == ds::kSkipVelocityY);
    CHECK(ds::skip_bit("tile-collisions-x") == ds::kSkipTileX);
    CHECK(ds::skip_bit("tile-collisions-y") == ds::kSkipTileY);
    CHECK(ds::skip_bit("on-solid") == ds::kSkipOnSolid);
    CHECK(ds::skip_bit("entity-collisions") == ds::kSkipEntityCollisions);
    CHECK(ds::skip_bit("tweens") == ds::kSkipTweens);
    CHECK(ds::skip_bit("velocity") == 0);
    CHECK(ds::skip_bit("jump") == 0);
    CHECK(ds::skip_bit("") == 0);
    CHECK(ds::skip_bit("Gravity") == 0);
    for (uint16_t bit : kAllSkips) {
        const char* name = ds::skip_name(bit);
        REQUIRE(name != nullptr);
        CHECK(ds::skip_bit(name) == bit);
    }
    CHECK(std::strcmp(ds::skip_name(ds::kSkipOnSolid), "on-solid") == 0);
}

TEST_CASE("Body::skips tests one bit") {
    Body b;
    b.skip = ds::kSkipGravity | ds::kSkipTweens;
    CHECK(b.skips(ds::kSkipGravity));
    CHECK(b.skips(ds::kSkipTweens));
    CHECK_FALSE(b.skips(ds::kSkipAcceleration));
    CHECK_FALSE(b.skips(ds::kSkipEntityCollisions));
}

// ---- changed_fields ---------------------------------------------------------

TEST_CASE("changed_fields reports exactly the fields whose value or exactness changed") {
    const Body a = faller(3, 0);
    Body b = a;
    CHECK(ds::changed_fields(a, b) == 0u);

    SUBCASE("value") {
        b.x = I(1);
        CHECK(ds::changed_fields(a, b) == ds::kFieldX);
    }
    SUBCASE("exactness alone") {
        b.vy = F(3);
        CHECK(ds::changed_fields(a, b) == ds::kFieldVy);
    }
    SUBCASE("flonum 0.0 vs -0.0") {
        Body c = a;
        c.vx = F(0.0);
        Body d = c;
        d.vx = F(-0.0);
        CHECK(ds::changed_fields(c, d) == ds::kFieldVx);
        CHECK(ds::changed_fields(d, c) == ds::kFieldVx);
    }
    SUBCASE("every field") {
        b.x = I(1);
        b.y = I(2);
        b.vx = I(3);
        b.vy = I(4);
        b.ay = I(5);
        b.on_ground = true;
        b.w = I(17);
        b.h = I(18);
        b.local_x = I(6);
        b.local_y = I(7);
        CHECK(ds::changed_fields(a, b) ==
              (ds::kFieldX | ds::kFieldY | ds::kFieldVx | ds::kFieldVy | ds::kFieldAy |
               ds::kFieldOnGround | ds::kFieldWidth | ds::kFieldHeight | ds::kFieldLocalX |
               ds::kFieldLocalY));
    }
    SUBCASE("each field on its own") {
        Body c = a;
        c.y = F(0.5);
        CHECK(ds::changed_fields(a, c) == ds::kFieldY);
        c = a;
        c.ay = I(-15);
        CHECK(ds::changed_fields(a, c) == ds::kFieldAy);
        c = a;
        c.on_ground = true;
        CHECK(ds::changed_fields(a, c) == ds::kFieldOnGround);
        c = a;
        c.w = F(16);
        CHECK(ds::changed_fields(a, c) == ds::kFieldWidth);
        c = a;
        c.h = I(1);
        CHECK(ds::changed_fields(a, c) == ds::kFieldHeight);
        c = a;
        c.local_x = F(0.0);
        CHECK(ds::changed_fields(a, c) == ds::kFieldLocalX);
        c = a;
        c.local_y = I(-3);
        CHECK(ds::changed_fields(a, c) == ds::kFieldLocalY);
    }
}

// ---- apply_acceleration -----------------------------------------------------

TEST_CASE("apply_acceleration: vy += ay, then ay becomes exact 0") {
    Body b = faller(5, -15);
    ds::apply_acceleration(b);
    CHECK_EXACT(b.vy, -10);
    CHECK_EXACT(b.ay, 0);
    CHECK_EXACT(b.y, 0);  // position untouched
    CHECK(ds::changed_fields(faller(5, -15), b) == (ds::kFieldVy | ds::kFieldAy));
}

TEST_CASE("apply_acceleration: a jump from rest") {
    Body b = faller(0, -ds::kJumpForce);
    ds::apply_acceleration(b);
    CHECK_EXACT(b.vy, -15);
    CHECK_EXACT(b.ay, 0);
}

TEST_CASE("apply_acceleration: flonum inputs") {
    SUBCASE("flonum ay: vy becomes flonum, ay exact 0") {
        Body b = faller(1, 0);
        b.ay = F(2.5);
        ds::apply_acceleration(b);
        CHECK_FLONUM(b.vy, 3.5);
        CHECK_EXACT(b.ay, 0);
    }
    SUBCASE("flonum vy, exact ay") {
        Body b = faller(0, -15);
        b.vy = F(0.5);
        ds::apply_acceleration(b);
        CHECK_FLONUM(b.vy, -14.5);
        CHECK_EXACT(b.ay, 0);
    }
    SUBCASE("integer-valued flonum ay") {
        Body b = faller(5, 0);
        b.ay = F(-15.0);
        ds::apply_acceleration(b);
        CHECK_FLONUM(b.vy, -10);
        CHECK_EXACT(b.ay, 0);
    }
}

TEST_CASE("apply_acceleration: ay exactly 0 is left as it is") {
    SUBCASE("exact 0: nothing changes at all") {
        const Body before = faller(5, 0);
        Body b = before;
        ds::apply_acceleration(b);
        CHECK(same_body(b, before));
        CHECK(ds::changed_fields(before, b) == 0u);
    }
    SUBCASE("flonum 0.0: ay stays flonum, but vy += 0.0 makes vy a flonum") {
        Body before = faller(5, 0);
        before.ay = F(0.0);
        Body b = before;
        ds::apply_acceleration(b);
        CHECK_FLONUM(b.vy, 5);
        CHECK_FLONUM(b.ay, 0);
        CHECK_FALSE(std::signbit(b.ay.v));
        CHECK(ds::changed_fields(before, b) == ds::kFieldVy);
    }
    SUBCASE("flonum -0.0 is zero too and stays as it is") {
        Body before = faller(5, 0);
        before.ay = F(-0.0);
        Body b = before;
        ds::apply_acceleration(b);
        CHECK_FLONUM(b.vy, 5);
        CHECK(ds::same(b.ay, F(-0.0)));
        CHECK(ds::changed_fields(before, b) == ds::kFieldVy);
    }
}

TEST_CASE("apply_acceleration: needs gravity? and is skipped by 'acceleration") {
    SUBCASE("gravity false") {
        Body before = faller(5, -15);
        before.gravity = false;
        Body b = before;
        ds::apply_acceleration(b);
        CHECK(same_body(b, before));
    }
    SUBCASE("skip acceleration") {
        Body before = faller(5, -15);
        before.skip = ds::kSkipAcceleration;
        Body b = before;
        ds::apply_acceleration(b);
        CHECK(same_body(b, before));
    }
    SUBCASE("every other skip bit leaves it running") {
        Body b = faller(5, -15);
        b.skip = kEverySkip & ~ds::kSkipAcceleration;
        ds::apply_acceleration(b);
        CHECK_EXACT(b.vy, -10);
        CHECK_EXACT(b.ay, 0);
    }
}

// ---- apply_gravity ----------------------------------------------------------

TEST_CASE("apply_gravity: vy += 1, exact stays exact") {
    Body b = faller(0, 0);
    ds::apply_gravity(b);
    CHECK_EXACT(b.vy, 1);
    ds::apply_gravity(b);
    CHECK_EXACT(b.vy, 2);
    Body up = faller(-15, 0);
    ds::apply_gravity(up);
    CHECK_EXACT(up.vy, -14);
    CHECK_EXACT(up.ay, 0);
    CHECK_EXACT(up.y, 0);
}

TEST_CASE("apply_gravity: flonum vy stays flonum") {
    Body b = faller(0, 0);
    b.vy = F(0.5);
    ds::apply_gravity(b);
    CHECK_FLONUM(b.vy, 1.5);
    b.vy = F(-1.0);
    ds::apply_gravity(b);
    CHECK_FLONUM(b.vy, 0);
}

TEST_CASE("apply_gravity: needs gravity? and is skipped by 'gravity") {
    SUBCASE("gravity false") {
        Body before = faller(3, 0);
        before.gravity = false;
        Body b = before;
        ds::apply_gravity(b);
        CHECK(same_body(b, before));
    }
    SUBCASE("skip gravity") {
        Body before = faller(3, 0);
        before.skip = ds::kSkipGravity;
        Body b = before;
        ds::apply_gravity(b);
        CHECK(same_body(b, before));
    }
    SUBCASE("every other skip bit leaves it running") {
        Body b = faller(3, 0);
        b.skip = kEverySkip & ~ds::kSkipGravity;
        ds::apply_gravity(b);
        CHECK_EXACT(b.vy, 4);
    }
}

// ---- apply_velocity ---------------------------------------------------------

TEST_CASE("apply_velocity_x: x += vx keeps exactness") {
    Body b = box(100, 7, 16, 16);
    b.vx = I(3);
    ds::apply_velocity_x(b);
    CHECK_EXACT(b.x, 103);
    CHECK_EXACT(b.vx, 3);
    CHECK_EXACT(b.y, 7);
    b.vx = I(-110);
    ds::apply_velocity_x(b);
    CHECK_EXACT(b.x, -7);
}

TEST_CASE("apply_velocity_x: any flonum input gives a flonum") {
    Body a = box(100, 0, 16, 16);
    a.vx = F(1.5);
    ds::apply_velocity_x(a);
    CHECK_FLONUM(a.x, 101.5);
    CHECK_FLONUM(a.vx, 1.5);

    Body b = box(100, 0, 16, 16);
    b.x = F(100);
    b.vx = I(3);
    ds::apply_velocity_x(b);
    CHECK_FLONUM(b.x, 103);

    Body c = box(100, 0, 16, 16);
    c.vx = F(0.0);  // (+ 100 0.0) is 100.0
    ds::apply_velocity_x(c);
    CHECK_FLONUM(c.x, 100);
}

TEST_CASE("apply_velocity_x: vx = 0 changes nothing") {
    const Body before = box(100, 0, 16, 16);
    Body b = before;
    ds::apply_velocity_x(b);
    CHECK(same_body(b, before));
    CHECK(ds::changed_fields(before, b) == 0u);
    Body f = box(0, 0, 16, 16);
    f.x = F(2.5);
    const Body fbefore = f;
    ds::apply_velocity_x(f);
    CHECK(same_body(f, fbefore));
}

TEST_CASE("apply_velocity_x: huge coordinates") {
    Body b = box(1e9, 0, 16, 16);
    b.vx = I(1);
    ds::apply_velocity_x(b);
    CHECK_EXACT(b.x, 1000000001.0);
    Body f = box(0, 0, 16, 16);
    f.x = F(1e12);
    f.vx = F(0.5);
    ds::apply_velocity_x(f);
    CHECK_FLONUM(f.x, 1000000000000.5);
}

TEST_CASE("apply_velocity_x does not need gravity? and is skipped by 'velocity-x") {
    Body b = box(10, 10, 16, 16);
    b.vx = I(2);
    b.vy = I(5);
    b.gravity = false;
    ds::apply_velocity_x(b);
    CHECK_EXACT(b.x, 12);
    CHECK_EXACT(b.y, 10);

    Body s = box(10, 10, 16, 16);
    s.vx = I(2);
    s.skip = ds::kSkipVelocityX;
    const Body before = s;
    ds::apply_velocity_x(s);
    CHECK(same_body(s, before));

    Body o = box(10, 10, 16, 16);
    o.vx = I(2);
    o.skip = kEverySkip & ~ds::kSkipVelocityX;
    ds::apply_velocity_x(o);
    CHECK_EXACT(o.x, 12);
}

TEST_CASE("apply_velocity_y: y += vy keeps exactness; skipped by 'velocity-y") {
    Body b = box(10, 10, 16, 16);
    b.vx = I(2);
    b.vy = I(-5);
    ds::apply_velocity_y(b);
    CHECK_EXACT(b.y, 5);
    CHECK_EXACT(b.x, 10);

    Body f = box(10, 10, 16, 16);
    f.vy = F(0.25);
    ds::apply_velocity_y(f);
    CHECK_FLONUM(f.y, 10.25);

    Body z = box(10, 10, 16, 16);
    const Body zb = z;
    ds::apply_velocity_y(z);
    CHECK(same_body(z, zb));

    Body s = box(10, 10, 16, 16);
    s.vy = I(5);
    s.skip = ds::kSkipVelocityY;
    const Body before = s;
    ds::apply_velocity_y(s);
    CHECK(same_body(s, before));

    Body o = box(10, 10, 16, 16);
    o.vy = I(5);
    o.skip = kEverySkip & ~ds::kSkipVelocityY;
    ds::apply_velocity_y(o);
    CHECK_EXACT(o.y, 15);
}

TEST_CASE("apply_velocity (legacy): both axes, each skippable on its own") {
    auto mover = [] {
        Body b = box(10, 20, 16, 16);
        b.vx = I(3);
        b.vy = I(-4);
        return b;
    };
    SUBCASE("no skips") {
        Body b = mover();
        ds::apply_velocity(b);
        CHECK_EXACT(b.x, 13);
        CHECK_EXACT(b.y, 16);
    }
    SUBCASE("skip velocity-x") {
        Body b = mover();
        b.skip = ds::kSkipVelocityX;
        ds::apply_velocity(b);
        CHECK_EXACT(b.x, 10);
        CHECK_EXACT(b.y, 16);
    }
    SUBCASE("skip velocity-y") {
        Body b = mover();
        b.skip = ds::kSkipVelocityY;
        ds::apply_velocity(b);
        CHECK_EXACT(b.x, 13);
        CHECK_EXACT(b.y, 20);
    }
    SUBCASE("skip both") {
        Body b = mover();
        b.skip = ds::kSkipVelocityX | ds::kSkipVelocityY;
        const Body before = b;
        ds::apply_velocity(b);
        CHECK(same_body(b, before));
    }
    SUBCASE("mixed exactness per axis") {
        Body b = mover();
        b.vx = F(0.5);
        ds::apply_velocity(b);
        CHECK_FLONUM(b.x, 10.5);
        CHECK_EXACT(b.y, 16);
    }
}

TEST_CASE("the motion steps touch only their own fields") {
    Body b = faller(2, -3);
    b.vx = I(4);
    b.local_x = I(9);
    b.local_y = F(1.5);
    b.on_ground = true;
    b.solid = true;
    b.id = 42;
    b.group = 7;
    const Body before = b;
    ds::apply_acceleration(b);
    ds::apply_gravity(b);
    ds::apply_velocity_x(b);
    ds::apply_velocity_y(b);
    CHECK_EXACT(b.vy, 0);  // 2 - 3 + 1
    CHECK_EXACT(b.ay, 0);
    CHECK_EXACT(b.x, 4);
    CHECK_EXACT(b.y, 0);
    CHECK(ds::changed_fields(before, b) == (ds::kFieldX | ds::kFieldVy | ds::kFieldAy));
    CHECK(b.on_ground);
    CHECK(b.solid);
    CHECK(b.id == 42);
    CHECK(b.group == 7);
    CHECK(ds::same(b.local_y, F(1.5)));
}

}  // TEST_SUITE
