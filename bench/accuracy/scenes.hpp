// SPDX-License-Identifier: MIT
// The scenes of `downstroke-bench accuracy`: small worlds built for one
// error each, so that the truth they are measured against is known.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "frame.hpp"

namespace bench::accuracy {

// A world's bodies with the grid they collide with. The grid lives on the
// heap so a Setup can be moved without invalidating World::grid.
struct Setup {
    std::string name;
    std::shared_ptr<const ds::TileGrid> grid;  // null: no tiles
    std::vector<ds::Body> bodies;

    ds::World world() const;
};

constexpr int kTile = 16;
constexpr double kJumpSpeed = -ds::kJumpForce;  // vy0, px/frame
constexpr int kJumpBox = 16;                    // the jumper is 16×16

// One jumper, no tiles, vy = −15 at y = 0: free flight.
Setup jump_free();
// One jumper standing exactly on a flat tile floor whose top is at floor_y().
Setup jump_floor();
double jump_floor_y();

// Projectiles for the tunneling test: 8×8, no gravity, not solid, one lane
// (a single tile row) ending in a one-tile-thick wall whose left face is at
// tunnel_wall_x(). For each speed v in 1..max_speed, one projectile per
// integer phase: it starts 1..v px short of the wall, so it reaches the wall
// within the first frame and every integer phase of the crossing is tried.
Setup tunnel_lane(int max_speed);
double tunnel_wall_x();
// The speed of each projectile of tunnel_lane, in body order.
std::vector<int> tunnel_speeds(int max_speed);

// A crowd of n solid 8×8 gravity boxes (vx −2…2) dropped into a walled
// arena (walls two tiles thick) with immovable 16×48 pillars on the floor.
Setup arena(int n);
// Columns of solid 8×8 boxes dropped from rising heights, slightly off
// centre, so they land on each other at increasing speeds, next to walls.
Setup drop();
// `height` solid 8×8 gravity boxes touching, bottom one exactly on a tile floor.
Setup stack(int height);
// bench's crowd scene (speed/scenes.cpp): stacks 8 high at rest on the floor,
// 1 px apart, with immovable pillars; n movers.
Setup resting_crowd(int n);

}  // namespace bench::accuracy
