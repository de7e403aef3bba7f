// SPDX-License-Identifier: MIT
// Settling (settle.hpp): the rules both whole-frame paths share, and the
// frames step-scene runs with them — a caller that knows which bodies come
// back as left (the same plist), plans, steps the awake ones with
// Frame::step_physics and records which settled.
#include <memory>
#include <new>
#include <vector>

#include "frame.hpp"
#include "settle.hpp"
#include "support.hpp"

using namespace dst;
using ds::FrameOptions;
using ds::SettleConditions;
using ds::Settling;
using ds::TileGrid;

namespace {

// One whole frame as the bindings run it, over bodies that stand for a list
// of plists: a body is handed back as left when it equals what the last
// frame returned at its position (for plists: the same object).
struct ListFrame {
    ds::Frame frame;
    Settling settling;
    std::vector<Body> returned;
    bool all_settled = false;

    void step(std::vector<Body>& bodies, const TileGrid* grid, const FrameOptions& opts = {}) {
        const bool colliders = ds::any_collider(bodies);
        if (settling.begin(bodies.size(), SettleConditions::of(grid, opts)))
            for (size_t i = 0; i < bodies.size(); ++i)
                settling.plan(i, i < returned.size() && same_body(bodies[i], returned[i]), false, bodies[i],
                              colliders);
        const std::vector<Body> before = bodies;
        frame.step_physics(bodies, grid, opts, {}, {}, settling.asleep());
        all_settled = true;
        for (size_t i = 0; i < bodies.size(); ++i)
            all_settled &= settling.settle(i, ds::changed_fields(before[i], bodies[i]) == 0, false, before[i],
                                           colliders);
        returned = bodies;
    }
    uint64_t stepped() const { return frame.stats().step[ds::kStepGravity].processed; }
};

Body sitter(double x) {  // resting on row 2 of a 16 px grid
    Body b = box(x, 16, 16, 16);
    b.gravity = true;
    b.on_ground = true;
    return b;
}

}  // namespace

TEST_SUITE("settle") {

TEST_CASE("a body settles when a frame leaves it as it was and it depends on nobody") {
    const Body b = sitter(0);
    Settling s;
    const auto c = SettleConditions::of(nullptr, FrameOptions{});
    CHECK_FALSE(s.begin(1, c));  // nothing is known yet
    CHECK(s.settle(0, true, false, b, false));
    CHECK_FALSE(s.settle(0, false, false, b, false));  // changed
    CHECK_FALSE(s.settle(0, true, true, b, false));    // has a tween
    Body solid = b;
    solid.solid = true;
    CHECK_FALSE(s.settle(0, true, false, solid, false));  // pushes and is pushed
    Body grouped = b;
    grouped.group = 3;
    CHECK_FALSE(s.settle(0, true, false, grouped, false));  // follows a group
    CHECK_FALSE(s.settle(0, true, false, b, true));  // looks for a supporter among colliders
    Body hover = b;
    hover.skip = ds::kSkipOnSolid;
    CHECK(s.settle(0, true, false, hover, true));  // does not look
}

TEST_CASE("a settled body sleeps only as left, without a tween, independent, under the same conditions") {
    const Body b = sitter(0);
    const auto c = SettleConditions::of(nullptr, FrameOptions{});
    Settling s;
    s.begin(1, c);
    s.settle(0, true, false, b, false);
    REQUIRE(s.begin(1, c));
    CHECK(s.plan(0, true, false, b, false));
    CHECK(s.asleep()[0] == 1);
    CHECK_FALSE(s.plan(0, false, false, b, false));  // handed back changed
    CHECK(s.asleep()[0] == 0);
    CHECK_FALSE(s.plan(0, true, true, b, false));   // a tween started
    CHECK_FALSE(s.plan(0, true, false, b, true));   // a solid body appeared to stand on
    // plan() in two halves decides the same.
    for (const bool colliders : {false, true}) {
        s.propose(0, true, false, b);
        CHECK(s.confirm(0, colliders) == s.plan(0, true, false, b, colliders));
    }
    // Other options, then the same again: the marks are gone.
    FrameOptions two;
    two.substeps = 2;
    CHECK_FALSE(s.holds(SettleConditions::of(nullptr, two)));
    CHECK(s.holds(c));
    CHECK_FALSE(s.begin(1, SettleConditions::of(nullptr, two)));
    CHECK_FALSE(s.plan(0, true, false, b, false));
    CHECK_FALSE(s.begin(1, c));
    CHECK_FALSE(s.settled(0));
    // dt is not a condition: only tweens read it.
    s.settle(0, true, false, b, false);
    FrameOptions slow;
    slow.dt = 100;
    CHECK(s.begin(1, SettleConditions::of(nullptr, slow)));
    CHECK(s.plan(0, true, false, b, false));
    // A body at this position that is not the one the mark was made for.
    s.forget(0);
    CHECK_FALSE(s.settled(0));
    s.forget(5);  // past the marks: nothing to forget
}

TEST_CASE("marks outlive a shorter list, but not other conditions") {
    // A list shrinks and grows back: its entities settled under the same
    // map, unchanged since, sleep again; had the map changed in between,
    // none of them would.
    const auto floor = grid({"....", "....", "####"});
    const auto bare = grid({"....", "....", "...."});
    const Body b = sitter(0);
    Settling s;
    s.begin(3, SettleConditions::of(&floor, {}));
    for (size_t i = 0; i < 3; ++i) s.settle(i, true, false, b, false);
    REQUIRE(s.begin(1, SettleConditions::of(&floor, {})));
    REQUIRE(s.begin(3, SettleConditions::of(&floor, {})));
    CHECK(s.plan(2, true, false, b, false));
    s.begin(1, SettleConditions::of(&bare, {}));
    s.settle(0, true, false, b, false);
    REQUIRE(s.begin(3, SettleConditions::of(&bare, {})));
    CHECK(s.plan(0, true, false, b, false));
    CHECK_FALSE(s.plan(2, true, false, b, false));  // settled on the floor, which this map lacks
}

TEST_CASE("step-scene's frames: settled bodies wake when the grid is edited in place") {
    auto g = grid({"....", "....", "####"});
    std::vector<Body> bodies = {sitter(16), sitter(48)};
    ListFrame f;
    for (int k = 0; k < 2; ++k) f.step(bodies, &g);
    REQUIRE(f.all_settled);
    REQUIRE(f.stepped() == 0);
    g.set_solid(1, 2, false);
    f.step(bodies, &g);
    CHECK(f.stepped() == 2);
    CHECK_EXACT(bodies[0].y, 17);
    CHECK_EXACT(bodies[0].vy, 1);
    CHECK(same_body(bodies[1], sitter(48)));
    CHECK_FALSE(f.all_settled);
    // The other one settles again under the edited grid.
    f.step(bodies, &g);
    f.step(bodies, &g);
    CHECK(f.stepped() == 1);
    CHECK(f.settling.settled(1));
}

TEST_CASE("step-scene's frames: settled bodies wake when a new grid is built where the old one was") {
    alignas(TileGrid) unsigned char storage[sizeof(TileGrid)];
    auto* floor = new (storage) TileGrid(grid({"....", "....", "####"}));
    std::vector<Body> bodies = {sitter(16)};
    ListFrame f;
    for (int k = 0; k < 2; ++k) f.step(bodies, floor);
    REQUIRE(f.stepped() == 0);
    const uint64_t settled_on = floor->revision();
    std::destroy_at(floor);
    auto* bare = new (storage) TileGrid(grid({"....", "....", "...."}));
    REQUIRE(static_cast<void*>(bare) == static_cast<void*>(floor));
    REQUIRE(bare->revision() != settled_on);
    f.step(bodies, bare);
    CHECK(f.stepped() == 1);
    CHECK_EXACT(bodies[0].y, 17);
    std::destroy_at(bare);
}

}  // TEST_SUITE
