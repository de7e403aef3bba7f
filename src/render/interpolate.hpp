// SPDX-License-Identifier: MIT
// Drawing between two physics steps (issue 37, "Fix Your Timestep!"): a
// window presents more often than a game steps, or out of step with it, so
// each entity and the camera are drawn at previous + α·(current − previous),
// α the fraction of a step the clock has run past the last one. Physics is
// untouched: only the views drawn are moved.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "scene_view.hpp"

namespace ds::render {

// A move longer than this between two steps, on either axis, is a teleport
// (a respawn, a door to elsewhere, a scene replaced): drawn where the body
// is, never smeared across the screen. Four 16 px tiles: faster than any
// body a game moves on purpose in one step at 60 Hz, a bullet included.
constexpr double kTeleportPx = 64;

// Moves each view of `now` to its place at α between its match in `before`
// and now. A view is matched by position in the list when the ids there
// agree (0: no id) and its size is the same, else by its id when it has
// one; a view with no match (it appeared), or one that moved more than
// kTeleportPx, stays where it is. `ids` are identity tags, one per view.
void interpolate_views(std::span<EntityView> now, std::span<const int64_t> now_ids,
                       std::span<const EntityView> before, std::span<const int64_t> before_ids, double alpha);

// One coordinate at α from `before` to `now`, or `now` past kTeleportPx.
double interpolated(double before, double now, double alpha);

}  // namespace ds::render
