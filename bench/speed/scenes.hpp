// SPDX-License-Identifier: MIT
// The benchmark scenes: plain data every path builds its own world from, so
// each path starts from the same bodies, tiles and velocities.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bench {

struct SceneBody {
    int64_t x = 0, y = 0, w = 0, h = 0;  // px, exact integers
    int64_t vx = 0, vy = 0;              // px/frame
    bool gravity = false, solid = false, immovable = false, on_ground = false;
    // Categories (semantics §13): an enemy is in the category enemy and
    // collides with enemy and default, so it meets every solid as a body
    // without categories does. A sensor is immovable (it never moves), not solid.
    bool enemy = false, sensor = false;
    // The shots scenes (semantics §10, §13): a shot is a sensor in the
    // category shot that collides with enemy; a target is an enemy that also
    // collides with shot. `contacts`: #:contacts? #t. `author_keys`: the
    // game's own keys (#:kind #:damage #:owner #:ttl), after the engine's or,
    // with `author_first`, before them. `bounce`: #:bounce 1.
    bool shot = false, target = false, contacts = false, author_keys = false, author_first = false;
    bool bounce = false;
    // Gravity and speed limits (semantics §14): #:gravity-scale 2, #:drag 1,
    // #:max-vx 4, #:max-vy 64 (the knobs scene).
    bool knobs = false;
    // The velocity the bounce update restores, with its sign flipped, on an
    // axis a collision zeroed (0: that axis does not bounce).
    int64_t rvx = 0, rvy = 0;
};

// A cell whose solid part is a collision polygon (semantics §12), in tile
// px, as Tiled's collision editor draws it; gid names it for the Scheme
// paths' make-tilemap (3 and up).
struct SceneShape {
    int col = 0, row = 0;
    int gid = 0;
    std::vector<std::pair<int, int>> polygon;
};

struct Scene {
    std::string name;
    int n = 0;  // the N asked for: the number of moving bodies
    // Tiles: cols × rows cells of tile px, row-major, 1 = solid.
    int cols = 0, rows = 0, tile = 16;
    std::vector<uint8_t> solid;
    std::vector<SceneShape> shapes;  // cells given a shape (their `solid` is 0)
    std::string map_path;  // set when the tiles come from a Tiled map (load-tilemap)
    std::vector<SceneBody> bodies;  // movers first, then immovable pillars
    bool bounce = false;            // run the bounce update after every frame
    bool bullets = false;           // Box2D: make movers bullet bodies
    bool settle_box2d = false;      // Box2D: step until asleep before warm-up
    // Step with resting contacts on (FrameOptions::resting_contacts, Scheme
    // resting-contacts?); Box2D paths ignore it (their stacks rest anyway).
    bool resting_contacts = false;
};

const std::vector<std::string>& scene_names();
bool is_scene(const std::string& name);
// Builds scene `name` with n movers; deterministic for a given (name, n).
Scene make_scene(const std::string& name, int n);

}  // namespace bench
