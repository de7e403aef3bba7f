// SPDX-License-Identifier: MIT
// Easing curves, tween timing and tween values (semantics §6).
#include <string>
#include <string_view>

#include "ease.hpp"
#include "support.hpp"
#include "tween.hpp"

using namespace dst;
using ds::Ease;
using ds::TweenPhase;
using ds::TweenProp;
using ds::TweenTiming;

namespace {

struct Named {
    const char* name;
    Ease ease;
};

constexpr Named kCurves[] = {
    {"linear", Ease::Linear},
    {"quad-in", Ease::QuadIn},         {"quad-out", Ease::QuadOut},
    {"quad-in-out", Ease::QuadInOut},  {"cubic-in", Ease::CubicIn},
    {"cubic-out", Ease::CubicOut},     {"cubic-in-out", Ease::CubicInOut},
    {"quart-in", Ease::QuartIn},       {"quart-out", Ease::QuartOut},
    {"quart-in-out", Ease::QuartInOut}, {"sine-in", Ease::SineIn},
    {"sine-out", Ease::SineOut},       {"sine-in-out", Ease::SineInOut},
    {"expo-in", Ease::ExpoIn},         {"expo-out", Ease::ExpoOut},
    {"expo-in-out", Ease::ExpoInOut},  {"back-in", Ease::BackIn},
    {"back-out", Ease::BackOut},       {"back-in-out", Ease::BackInOut},
    {"elastic-in", Ease::ElasticIn},   {"elastic-out", Ease::ElasticOut},
    {"elastic-in-out", Ease::ElasticInOut}, {"bounce-in", Ease::BounceIn},
    {"bounce-out", Ease::BounceOut},   {"bounce-in-out", Ease::BounceInOut},
};

TweenTiming timing(double duration, double delay = 0, int64_t repeat = 0, bool yoyo = false) {
    TweenTiming t;
    t.duration = duration;
    t.delay = delay;
    t.repeat = repeat;
    t.yoyo = yoyo;
    return t;
}

TweenPhase running(double t, bool reversed = false) {
    TweenPhase p;
    p.started = true;
    p.t = t;
    p.reversed = reversed;
    return p;
}

TweenPhase done(bool reversed) {
    TweenPhase p;
    p.started = true;
    p.finished = true;
    p.t = 1;
    p.reversed = reversed;
    return p;
}

TweenProp prop(ds::Num start, ds::Num end) {
    TweenProp p;
    p.key = 0;
    p.start = start;
    p.end = end;
    return p;
}

}  // namespace

TEST_SUITE("tween") {

// ---- names ------------------------------------------------------------------

TEST_CASE("ease_from_name / ease_name: every curve by name") {
    for (const auto& c : kCurves) {
        const std::string name(c.name);
        CAPTURE(name);
        Ease e = Ease::Custom;
        REQUIRE(ds::ease_from_name(c.name, e));
        CHECK(e == c.ease);
        CHECK(ds::ease_name(c.ease) == std::string_view(c.name));
    }
}

TEST_CASE("ease_from_name fails on unknown names") {
    Ease e = Ease::Linear;
    CHECK_FALSE(ds::ease_from_name("quad", e));
    CHECK_FALSE(ds::ease_from_name("linear-in", e));
    CHECK_FALSE(ds::ease_from_name("quad-inout", e));
    CHECK_FALSE(ds::ease_from_name("ease-in", e));
    CHECK_FALSE(ds::ease_from_name("", e));
    CHECK_FALSE(ds::ease_from_name("quad-in ", e));
    CHECK_FALSE(ds::ease_from_name("circ-in", e));
    CHECK_FALSE(ds::ease_from_name("custom", e));
}

// ---- curves -----------------------------------------------------------------

TEST_CASE("every curve starts at 0 and ends at 1") {
    for (const auto& c : kCurves) {
        const std::string name(c.name);
        CAPTURE(name);
        CHECK(ds::ease(c.ease, 0.0) == 0.0);
        CHECK(ds::ease(c.ease, 1.0) == 1.0);
    }
}

TEST_CASE("t outside [0, 1] is clamped") {
    for (const auto& c : kCurves) {
        const std::string name(c.name);
        CAPTURE(name);
        CHECK(ds::ease(c.ease, -0.5) == 0.0);
        CHECK(ds::ease(c.ease, 1.5) == 1.0);
        CHECK(ds::ease(c.ease, 100.0) == 1.0);
    }
}

TEST_CASE("polynomial curves") {
    using doctest::Approx;
    CHECK(ds::ease(Ease::Linear, 0.25) == Approx(0.25));
    CHECK(ds::ease(Ease::Linear, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::QuadIn, 0.5) == Approx(0.25));
    CHECK(ds::ease(Ease::QuadOut, 0.5) == Approx(0.75));
    CHECK(ds::ease(Ease::QuadInOut, 0.25) == Approx(0.125));
    CHECK(ds::ease(Ease::QuadInOut, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::QuadInOut, 0.75) == Approx(0.875));
    CHECK(ds::ease(Ease::CubicIn, 0.5) == Approx(0.125));
    CHECK(ds::ease(Ease::CubicOut, 0.5) == Approx(0.875));
    CHECK(ds::ease(Ease::CubicInOut, 0.25) == Approx(0.0625));
    CHECK(ds::ease(Ease::CubicInOut, 0.75) == Approx(0.9375));
    CHECK(ds::ease(Ease::QuartIn, 0.5) == Approx(0.0625));
    CHECK(ds::ease(Ease::QuartOut, 0.5) == Approx(0.9375));
    CHECK(ds::ease(Ease::QuartInOut, 0.25) == Approx(0.03125));
    CHECK(ds::ease(Ease::QuartInOut, 0.75) == Approx(0.96875));
}

TEST_CASE("sine and expo curves") {
    using doctest::Approx;
    CHECK(ds::ease(Ease::SineIn, 0.5) == Approx(0.2928932188134524));
    CHECK(ds::ease(Ease::SineIn, 0.25) == Approx(0.07612046748871326));
    CHECK(ds::ease(Ease::SineOut, 0.5) == Approx(0.7071067811865475));
    CHECK(ds::ease(Ease::SineOut, 0.25) == Approx(0.3826834323650898));
    CHECK(ds::ease(Ease::SineInOut, 0.25) == Approx(0.1464466094067262));
    CHECK(ds::ease(Ease::SineInOut, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::SineInOut, 0.75) == Approx(0.8535533905932737));
    CHECK(ds::ease(Ease::ExpoIn, 0.5) == Approx(0.03125));
    CHECK(ds::ease(Ease::ExpoOut, 0.5) == Approx(0.96875));
    CHECK(ds::ease(Ease::ExpoInOut, 0.25) == Approx(0.015625));
    CHECK(ds::ease(Ease::ExpoInOut, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::ExpoInOut, 0.75) == Approx(0.984375));
}

TEST_CASE("back curves overshoot (c1 = 1.70158)") {
    using doctest::Approx;
    CHECK(ds::ease(Ease::BackIn, 0.25) == Approx(-0.06413656250000001));
    CHECK(ds::ease(Ease::BackIn, 0.5) == Approx(-0.08769750000000004));
    CHECK(ds::ease(Ease::BackIn, 0.9) == Approx(0.5911720200000001));
    CHECK(ds::ease(Ease::BackOut, 0.5) == Approx(1.0876975));
    CHECK(ds::ease(Ease::BackOut, 0.75) == Approx(1.0641365625));
    CHECK(ds::ease(Ease::BackInOut, 0.25) == Approx(-0.09968184375));
    CHECK(ds::ease(Ease::BackInOut, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::BackInOut, 0.75) == Approx(1.09968184375));
}

TEST_CASE("elastic curves (c4 = 2π/3, c5 = 2π/4.5)") {
    using doctest::Approx;
    CHECK(ds::ease(Ease::ElasticIn, 0.25) == Approx(-0.005524271728019903));
    CHECK(ds::ease(Ease::ElasticIn, 0.5) == Approx(-0.015625));
    CHECK(ds::ease(Ease::ElasticIn, 0.9) == Approx(-0.25));
    CHECK(ds::ease(Ease::ElasticOut, 0.25) == Approx(0.9116116523516816));
    CHECK(ds::ease(Ease::ElasticOut, 0.5) == Approx(1.015625));
    CHECK(ds::ease(Ease::ElasticOut, 0.9) == Approx(0.998046875));
    CHECK(ds::ease(Ease::ElasticInOut, 0.25) == Approx(0.011969444423734044));
    CHECK(ds::ease(Ease::ElasticInOut, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::ElasticInOut, 0.75) == Approx(0.988030555576266));
}

TEST_CASE("bounce curves (n1 = 7.5625, d1 = 2.75)") {
    using doctest::Approx;
    CHECK(ds::ease(Ease::BounceOut, 0.25) == Approx(0.47265625));
    CHECK(ds::ease(Ease::BounceOut, 0.5) == Approx(0.765625));
    CHECK(ds::ease(Ease::BounceOut, 0.75) == Approx(0.97265625));
    CHECK(ds::ease(Ease::BounceOut, 0.9) == Approx(0.988125));
    CHECK(ds::ease(Ease::BounceIn, 0.25) == Approx(0.02734375));
    CHECK(ds::ease(Ease::BounceIn, 0.5) == Approx(0.234375));
    CHECK(ds::ease(Ease::BounceIn, 0.9) == Approx(0.924375));
    CHECK(ds::ease(Ease::BounceInOut, 0.25) == Approx(0.1171875));
    CHECK(ds::ease(Ease::BounceInOut, 0.5) == Approx(0.5));
    CHECK(ds::ease(Ease::BounceInOut, 0.75) == Approx(0.8828125));
}

TEST_CASE("in-out curves are symmetric: f(1 - t) = 1 - f(t)") {
    using doctest::Approx;
    const Ease inouts[] = {Ease::QuadInOut,    Ease::CubicInOut, Ease::QuartInOut,
                           Ease::SineInOut,    Ease::ExpoInOut,  Ease::BackInOut,
                           Ease::ElasticInOut, Ease::BounceInOut};
    for (Ease e : inouts) {
        const std::string name(ds::ease_name(e));
        CAPTURE(name);
        for (double t : {0.1, 0.2, 0.3, 0.4}) {
            CAPTURE(t);
            CHECK(ds::ease(e, 1 - t) == Approx(1 - ds::ease(e, t)));
        }
    }
}

TEST_CASE("out curves mirror in curves: out(t) = 1 - in(1 - t)") {
    using doctest::Approx;
    const Ease pairs[][2] = {{Ease::QuadIn, Ease::QuadOut},       {Ease::CubicIn, Ease::CubicOut},
                             {Ease::QuartIn, Ease::QuartOut},     {Ease::SineIn, Ease::SineOut},
                             {Ease::ExpoIn, Ease::ExpoOut},       {Ease::BackIn, Ease::BackOut},
                             {Ease::ElasticIn, Ease::ElasticOut}, {Ease::BounceIn, Ease::BounceOut}};
    for (const auto& p : pairs) {
        const std::string name(ds::ease_name(p[0]));
        CAPTURE(name);
        for (double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
            CAPTURE(t);
            CHECK(ds::ease(p[1], t) == Approx(1 - ds::ease(p[0], 1 - t)));
        }
    }
}

// ---- tween_phase ------------------------------------------------------------

TEST_CASE("tween_phase: the delay, then one cycle") {
    const TweenTiming tm = timing(100, 50);
    TweenPhase p = ds::tween_phase(tm, 0);
    CHECK_FALSE(p.started);
    CHECK_FALSE(p.finished);
    p = ds::tween_phase(tm, 49.9);
    CHECK_FALSE(p.started);
    CHECK_FALSE(p.finished);
    p = ds::tween_phase(tm, 50);
    CHECK(p.started);
    CHECK_FALSE(p.finished);
    CHECK(p.t == 0.0);
    CHECK_FALSE(p.reversed);
    p = ds::tween_phase(tm, 75);
    CHECK(p.started);
    CHECK(p.t == 0.25);
    p = ds::tween_phase(tm, 149.5);
    CHECK_FALSE(p.finished);
    CHECK(p.t == doctest::Approx(0.995));
    p = ds::tween_phase(tm, 150);
    CHECK(p.started);
    CHECK(p.finished);
    CHECK_FALSE(p.reversed);
    p = ds::tween_phase(tm, 1e6);
    CHECK(p.finished);
    CHECK_FALSE(p.reversed);
}

TEST_CASE("tween_phase: no delay") {
    const TweenTiming tm = timing(200);
    TweenPhase p = ds::tween_phase(tm, 0);
    CHECK(p.started);
    CHECK_FALSE(p.finished);
    CHECK(p.t == 0.0);
    p = ds::tween_phase(tm, 50);
    CHECK(p.t == 0.25);
    p = ds::tween_phase(tm, 200);
    CHECK(p.finished);
}

TEST_CASE("tween_phase: duration 0 finishes as soon as the delay is over") {
    const TweenTiming tm = timing(0, 10);
    TweenPhase p = ds::tween_phase(tm, 5);
    CHECK_FALSE(p.started);
    CHECK_FALSE(p.finished);
    p = ds::tween_phase(tm, 10);
    CHECK(p.started);
    CHECK(p.finished);
    CHECK_FALSE(p.reversed);
    p = ds::tween_phase(timing(0), 0);
    CHECK(p.finished);
    p = ds::tween_phase(timing(0, 0, 3), 0);  // repeats of nothing take no time either
    CHECK(p.finished);
}

TEST_CASE("tween_phase: repeat N replays N more cycles; the delay comes only once") {
    const TweenTiming tm = timing(100, 50, 2);
    TweenPhase p = ds::tween_phase(tm, 175);  // cycle 1 spans [150, 250)
    CHECK(p.started);
    CHECK_FALSE(p.finished);
    CHECK(p.t == 0.25);
    CHECK_FALSE(p.reversed);
    p = ds::tween_phase(tm, 250);  // cycle 2 begins
    CHECK_FALSE(p.finished);
    CHECK(p.t == 0.0);
    p = ds::tween_phase(tm, 300);
    CHECK(p.t == 0.5);
    p = ds::tween_phase(tm, 349);
    CHECK_FALSE(p.finished);
    CHECK(p.t == doctest::Approx(0.99));
    p = ds::tween_phase(tm, 350);  // 50 + 3 * 100
    CHECK(p.finished);
    CHECK_FALSE(p.reversed);
}

TEST_CASE("tween_phase: yoyo reverses odd cycles") {
    const TweenTiming tm = timing(100, 0, 1, true);
    TweenPhase p = ds::tween_phase(tm, 50);
    CHECK_FALSE(p.reversed);
    CHECK(p.t == 0.5);
    p = ds::tween_phase(tm, 100);  // cycle 1 begins, reversed
    CHECK_FALSE(p.finished);
    CHECK(p.reversed);
    CHECK(p.t == 0.0);
    p = ds::tween_phase(tm, 125);
    CHECK(p.reversed);
    CHECK(p.t == 0.25);
    p = ds::tween_phase(tm, 200);  // finished after the reversed cycle: back at the start
    CHECK(p.finished);
    CHECK(p.reversed);
}

TEST_CASE("tween_phase: yoyo finishing after an even number of reversals") {
    const TweenTiming tm = timing(100, 10, 2, true);  // cycles: fwd, back, fwd
    TweenPhase p = ds::tween_phase(tm, 260);  // cycle 2 at t = 0.5
    CHECK_FALSE(p.reversed);
    CHECK(p.t == 0.5);
    p = ds::tween_phase(tm, 310);
    CHECK(p.finished);
    CHECK_FALSE(p.reversed);
    // yoyo with no repeat never reverses
    p = ds::tween_phase(timing(100, 0, 0, true), 100);
    CHECK(p.finished);
    CHECK_FALSE(p.reversed);
}

TEST_CASE("tween_phase: without yoyo repeats never reverse") {
    const TweenTiming tm = timing(100, 0, 3);
    for (double e : {50.0, 150.0, 250.0, 350.0}) {
        TweenPhase p = ds::tween_phase(tm, e);
        CHECK_FALSE(p.reversed);
        CHECK(p.t == 0.5);
    }
    CHECK(ds::tween_phase(tm, 400).finished);
    CHECK_FALSE(ds::tween_phase(tm, 400).reversed);
}

TEST_CASE("tween_phase: repeat -1 runs forever") {
    const TweenTiming tm = timing(100, 0, -1, true);
    TweenPhase p = ds::tween_phase(tm, 1050);  // cycle 10
    CHECK_FALSE(p.finished);
    CHECK_FALSE(p.reversed);
    CHECK(p.t == 0.5);
    p = ds::tween_phase(tm, 1150);  // cycle 11
    CHECK_FALSE(p.finished);
    CHECK(p.reversed);
    CHECK(p.t == 0.5);
    p = ds::tween_phase(tm, 1e9 + 25);
    CHECK(p.started);
    CHECK_FALSE(p.finished);
    CHECK(p.t == doctest::Approx(0.25));
    CHECK_FALSE(ds::tween_phase(timing(100, 0, -1), 1e12).finished);
}

// ---- tween_value ------------------------------------------------------------

TEST_CASE("tween_value: intermediate values are flonums") {
    const TweenProp p = prop(I(0), I(200));
    CHECK_FLONUM(ds::tween_value(p, running(0.5), 0.5), 100);
    CHECK_FLONUM(ds::tween_value(p, running(0.25), 0.25), 50);
    CHECK_FLONUM(ds::tween_value(p, running(0.0), 0.0), 0);
    // the eased value is used, not t
    CHECK_FLONUM(ds::tween_value(p, running(0.5), 0.25), 50);
    // overshoot is not clamped
    CHECK_FLONUM(ds::tween_value(p, running(0.5), 1.5), 300);
    const TweenProp down = prop(I(100), I(-100));
    CHECK_FLONUM(ds::tween_value(down, running(0.25), 0.25), 50);
}

TEST_CASE("tween_value: reversed cycles run end → start") {
    const TweenProp p = prop(I(0), I(200));
    CHECK_FLONUM(ds::tween_value(p, running(0.25, true), 0.25), 150);
    CHECK_FLONUM(ds::tween_value(p, running(0.0, true), 0.0), 200);
}

TEST_CASE("tween_value: a finished tween writes the target itself") {
    const TweenProp p = prop(I(0), I(200));
    CHECK_EXACT(ds::tween_value(p, done(false), 1.0), 200);
    CHECK_EXACT(ds::tween_value(p, done(true), 1.0), 0);
    const TweenProp f = prop(I(0), F(7.5));
    CHECK_FLONUM(ds::tween_value(f, done(false), 1.0), 7.5);
    CHECK_EXACT(ds::tween_value(f, done(true), 1.0), 0);
    const TweenProp g = prop(F(2.0), I(8));
    CHECK_FLONUM(ds::tween_value(g, done(true), 1.0), 2);
    CHECK_EXACT(ds::tween_value(g, done(false), 1.0), 8);
    // whatever the eased value says
    CHECK_EXACT(ds::tween_value(p, done(false), 0.3), 200);
}

TEST_CASE("tween_value: intermediate values from flonum ends") {
    const TweenProp p = prop(F(0.5), F(1.5));
    CHECK_FLONUM(ds::tween_value(p, running(0.5), 0.5), 1.0);
    const TweenProp q = prop(I(-1000000000), I(1000000000));
    CHECK_FLONUM(ds::tween_value(q, running(0.75), 0.75), 500000000);
}

}  // TEST_SUITE
