// SPDX-License-Identifier: MIT
// Gravity and speed limits (semantics §14): #:gravity-scale, #:drag,
// #:max-vx and #:max-vy, alone and in a whole frame with sub-frames.
#include "frame.hpp"
#include "steps.hpp"
#include "support.hpp"

using namespace dst;
using ds::DragNum;
using ds::Frame;
using ds::FrameOptions;
using ds::SpeedCap;
using ds::World;

namespace {

Body mover(Num vx, Num vy) {
    Body b = box(0, 0, 8, 8);
    b.vx = vx;
    b.vy = vy;
    return b;
}

FrameOptions substeps(int k) {
    FrameOptions o;
    o.substeps = k;
    return o;
}

}  // namespace

TEST_SUITE("knobs") {

TEST_CASE("apply_gravity: gravity × #:gravity-scale, exact × exact stays exact") {
    Body b = mover(I(0), I(0));
    b.gravity = true;
    b.gravity_scale.n = I(-1);  // falls up
    ds::apply_gravity(b);
    CHECK_EXACT(b.vy, -1);
    b.gravity_scale.n = I(0);  // floats: adds an exact 0
    CHECK(ds::apply_gravity(b));
    CHECK_EXACT(b.vy, -1);
    b.gravity_scale.n = F(0.25);
    ds::apply_gravity(b);
    CHECK_FLONUM(b.vy, -0.75);
    b.gravity_scale.n = I(3);
    b.vy = I(2);
    ds::apply_gravity(b, ds::SubStep::of_frame(4));  // 3 · 1/4, a flonum
    CHECK_FLONUM(b.vy, 2.75);
}

TEST_CASE("apply_speed_limits: drag moves toward 0 and never past it") {
    Body b = mover(I(5), I(-5));
    b.drag = DragNum::of(I(2));
    CHECK(ds::apply_speed_limits(b));
    CHECK_EXACT(b.vx, 3);
    CHECK_EXACT(b.vy, -3);
    ds::apply_speed_limits(b);
    ds::apply_speed_limits(b);
    CHECK_EXACT(b.vx, 0);  // 1 is within 2 of 0: it stops
    CHECK_EXACT(b.vy, 0);
    Body f = mover(F(1.5), I(1));
    f.drag = DragNum::of(F(0.5));
    ds::apply_speed_limits(f);
    CHECK_FLONUM(f.vx, 1.0);
    CHECK_FLONUM(f.vy, 0.5);
    ds::apply_speed_limits(f);
    ds::apply_speed_limits(f);
    CHECK_FLONUM(f.vx, 0.0);
    CHECK_FLONUM(f.vy, 0.0);  // stopped by a flonum drag: a flonum 0
    Body still = mover(I(0), F(-0.0));
    still.drag = DragNum::of(F(0.5));
    ds::apply_speed_limits(still);
    CHECK_EXACT(still.vx, 0);  // a still velocity is left as it is
    CHECK(std::signbit(still.vy.v));
}

TEST_CASE("apply_speed_limits: the caps clamp |vx| and |vy|, after the drag") {
    Body b = mover(I(10), I(-12));
    b.drag = DragNum::of(I(2));
    b.max_vx = SpeedCap::of(I(5));
    b.max_vy = SpeedCap::of(F(6));
    ds::apply_speed_limits(b);
    CHECK_EXACT(b.vx, 5);  // 10 − 2 = 8, then 5
    CHECK_FLONUM(b.vy, -6.0);
    Body zero = mover(I(-3), I(4));
    zero.max_vx = SpeedCap::of(F(0.0));  // a zero cap reads as exact 0
    ds::apply_speed_limits(zero);
    CHECK_EXACT(zero.vx, 0);
    CHECK_FALSE(std::signbit(zero.vx.v));
    CHECK_EXACT(zero.vy, 4);  // no cap on y
}

TEST_CASE("apply_speed_limits: none of the keys, or 'speed-limits skipped, leaves the body alone") {
    Body plain = mover(I(100), F(-100));
    const Body before = plain;
    CHECK_FALSE(ds::apply_speed_limits(plain));
    CHECK(ds::changed_fields(before, plain) == 0);
    Body skipped = mover(I(100), I(0));
    skipped.max_vx = SpeedCap::of(I(1));
    skipped.skip = ds::kSkipSpeedLimits;
    CHECK_FALSE(ds::apply_speed_limits(skipped));
    CHECK_EXACT(skipped.vx, 100);
    Body within = mover(I(3), I(0));
    within.max_vx = SpeedCap::of(I(3));
    CHECK(ds::apply_speed_limits(within));  // applies, changes nothing
    CHECK_EXACT(within.vx, 3);
}

TEST_CASE("a frame: terminal velocity after gravity, with or without #:gravity?") {
    World w;
    Body faller = mover(I(0), I(0));
    faller.gravity = true;
    faller.max_vy = SpeedCap::of(I(3));
    Body ship = mover(I(7), I(0));  // a top-down body: no gravity
    ship.drag = DragNum::of(I(1));
    ship.max_vx = SpeedCap::of(I(4));
    w.bodies = {faller, ship};
    Frame f;
    const double ys[] = {1, 3, 6, 9, 12};  // vy 1, 2, 3, 3, 3
    const double xs[] = {4, 7, 9, 10, 10};  // vx 4 (7 − 1, capped), 3, 2, 1, 0
    for (int t = 0; t < 5; ++t) {
        f.step(w, {});
        CHECK_EXACT(w.bodies[0].y, ys[t]);
        CHECK_EXACT(w.bodies[1].x, xs[t]);
    }
    CHECK(f.stats().step[ds::kStepSpeedLimits].processed == 2);
    CHECK(f.stats().step[ds::kStepSpeedLimits].skipped == 0);
}

TEST_CASE("sub-frames: drag takes its share in each, the cap holds in each") {
    World w;
    Body b = mover(I(8), I(0));
    b.drag = DragNum::of(I(2));
    Body c = mover(I(0), I(0));
    c.gravity = true;
    c.max_vy = SpeedCap::of(I(1));
    w.bodies = {b, c};
    Frame f;
    f.step(w, substeps(4));
    // vx 7.5, 7, 6.5, 6 over quarter frames: x = (7.5 + 7 + 6.5 + 6) / 4
    CHECK_FLONUM(w.bodies[0].vx, 6.0);
    CHECK_FLONUM(w.bodies[0].x, 6.75);
    // vy 0.25, 0.5, 0.75, 1 (the cap is exact: at 1 it is not passed)
    CHECK_FLONUM(w.bodies[1].vy, 1.0);
    CHECK_FLONUM(w.bodies[1].y, 0.625);
    f.step(w, substeps(4));
    CHECK_EXACT(w.bodies[1].vy, 1);  // each sub-frame clamps 1.25 to the exact cap
    CHECK_FLONUM(w.bodies[1].y, 1.625);
}

}  // TEST_SUITE
