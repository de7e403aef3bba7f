// SPDX-License-Identifier: MIT
#include "speed/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "frame.hpp"
#include "tilemap/tilemap.hpp"

namespace bench {

namespace {

constexpr int kTile = 16;

int ceil_sqrt(double v) { return static_cast<int>(std::ceil(std::sqrt(v))); }

struct Grid {
    int cols, rows;
    std::vector<uint8_t> cells;
    Grid(int c, int r) : cols(c), rows(r), cells(static_cast<size_t>(c) * r, 0) {}
    void set(int c, int r) {
        if (c >= 0 && r >= 0 && c < cols && r < rows) cells[static_cast<size_t>(r) * cols + c] = 1;
    }
    bool get(int c, int r) const { return cells[static_cast<size_t>(r) * cols + c] != 0; }
    void walls() {  // a 1-tile border on all four sides
        for (int c = 0; c < cols; ++c) set(c, 0), set(c, rows - 1);
        for (int r = 0; r < rows; ++r) set(0, r), set(cols - 1, r);
    }
};

void take(Scene& s, Grid&& g) {
    s.cols = g.cols;
    s.rows = g.rows;
    s.tile = kTile;
    s.solid = std::move(g.cells);
}

SceneBody box(int64_t x, int64_t y, int64_t size) {
    SceneBody b;
    b.x = x;
    b.y = y;
    b.w = b.h = size;
    return b;
}

// rain: 8×8 gravity boxes (not solid, vx −1, 0 or 1) in 10 rows one tile
// apart, above a row of 4-tile platforms and a floor; the rows get wider
// with N, so every N goes through the same motion (all land by frame ~25).
Scene rain(int n) {
    Scene s;
    constexpr int kSpawnRows = 10;
    const int per_row = (n + kSpawnRows - 1) / kSpawnRows;
    const int cols = per_row + 2, rows = kSpawnRows + 10;
    Grid g(cols, rows);
    for (int r = 0; r < rows; ++r) g.set(0, r), g.set(cols - 1, r);
    for (int c = 0; c < cols; ++c) g.set(c, rows - 1), g.set(c, rows - 2);
    const int platform_row = kSpawnRows + 4;
    for (int c = 1; c < cols - 1; ++c)
        if ((c - 1) % 12 >= 3 && (c - 1) % 12 <= 6) g.set(c, platform_row);
    for (int i = 0; i < n; ++i) {
        SceneBody b = box((1 + i % per_row) * kTile + 4, (1 + i / per_row) * kTile + 4, 8);
        b.vx = i % 3 - 1;
        b.gravity = true;
        s.bodies.push_back(b);
    }
    take(s, std::move(g));
    return s;
}

// ramps: rain over hills. The platforms of rain become hills with 45°
// sides, and the floor between them rises and falls in 1:2 ramps, so most
// boxes land on a ramp and walk (vx −1, 0, 1) up and down it. ramps-flat is
// the same map with every ramp cell empty, so its walkers walk as far on
// flat ground (ramp cells made whole blocks would stop them, and a stopped
// box costs less): the cost of the shapes is ramps ÷ ramps-flat, measured in
// one run.
Scene ramps(int n, bool flat) {
    Scene s = rain(n);
    Grid g(s.cols, s.rows);
    g.cells = s.solid;
    const int platform_row = 10 + 4, bump_row = s.rows - 3;
    const std::vector<std::pair<int, int>> up45 = {{0, 16}, {16, 16}, {16, 0}}, down45 = {{0, 0}, {0, 16}, {16, 16}};
    const std::vector<std::pair<int, int>> up12a = {{0, 16}, {16, 16}, {16, 8}}, up12b = {{0, 16}, {16, 16}, {16, 0}, {0, 8}};
    const std::vector<std::pair<int, int>> down12b = {{0, 0}, {0, 16}, {16, 16}, {16, 8}}, down12a = {{0, 8}, {0, 16}, {16, 16}};
    auto put = [&](int c, int r, int gid, const std::vector<std::pair<int, int>>& poly) {
        if (c <= 0 || c >= s.cols - 1) return;
        g.cells[static_cast<size_t>(r) * s.cols + c] = 0;
        if (!flat) s.shapes.push_back({c, r, gid, poly});
    };
    for (int c = 1; c < s.cols - 1; ++c) {
        const int k = (c - 1) % 12;
        if (k == 3) put(c, platform_row, 3, up45);
        if (k == 6) put(c, platform_row, 4, down45);
        if (k == 8) put(c, bump_row, 5, up12a);
        if (k == 9) put(c, bump_row, 6, up12b);
        if (k == 10) put(c, bump_row, 7, down12b);
        if (k == 11) put(c, bump_row, 8, down12a);
    }
    s.solid = std::move(g.cells);
    return s;
}

// crowd: solid 8×8 gravity boxes in stacks 8 high from the floor up
// (touching vertically, 1 px apart horizontally) in a walled arena, with an
// immovable 16×32 pillar after every 16 stacks; the arena gets wider with N.
Scene crowd(int n) {
    Scene s;
    const int height = 8;
    const int columns = (n + height - 1) / height;
    std::vector<int64_t> column_x, pillar_x;
    int64_t cursor = kTile + 4;
    for (int j = 0; j < columns; ++j) {
        if (j > 0 && j % 16 == 0) {
            pillar_x.push_back(cursor + 2);
            cursor += 20;
        }
        column_x.push_back(cursor);
        cursor += 9;
    }
    const int cols = static_cast<int>((cursor + 4 + kTile - 1) / kTile) + 1;
    const int rows = (height * 8 + 48 + kTile - 1) / kTile + 2;
    Grid g(cols, rows);
    g.walls();
    const int64_t floor_y = static_cast<int64_t>(rows - 1) * kTile;
    for (int i = 0; i < n; ++i) {
        SceneBody b = box(column_x[i % columns], floor_y - 8 * (i / columns + 1), 8);
        b.gravity = b.solid = true;
        s.bodies.push_back(b);
    }
    for (int64_t x : pillar_x) {
        SceneBody p = box(x, floor_y - 32, 16);
        p.h = 32;
        p.solid = p.immovable = true;
        s.bodies.push_back(p);
    }
    take(s, std::move(g));
    return s;
}

// knobs: rain standing still sideways (vx 0), every box using all four
// speed keys of semantics §14: #:gravity-scale 2 less #:drag 1 falls
// exactly as gravity 1 does (vy 1, 2, 3, …, exact), #:max-vx 4 and
// #:max-vy 64 are checked every frame and never reached. knobs-off is the
// same boxes without the keys: the same motion, so knobs ÷ knobs-off, in
// one run, is what the keys cost when every body uses them. Every box has
// landed by frame ~25 and then sleeps: time the fall (--warmup 0).
Scene knobs(int n, bool keys) {
    Scene s = rain(n);
    for (SceneBody& b : s.bodies) {
        b.vx = 0;
        b.knobs = keys;
    }
    return s;
}

// crowd-categories: crowd with every other box an enemy (in the category
// enemy, colliding with enemy and default). Every pair still meets, so the
// boxes move exactly as in crowd: crowd-categories ÷ crowd, in one run, is
// what the category test costs when half the bodies use it.
Scene crowd_categories(int n) {
    Scene s = crowd(n);
    for (size_t i = 0; i < s.bodies.size(); i += 2)
        if (!s.bodies[i].immovable) s.bodies[i].enemy = true;
    return s;
}

// crowd-sensors: crowd with one 8×32 sensor per ten boxes, over every tenth
// box and the ones stacked on it. crowd-sensors ÷ crowd is what n/10
// sensors cost among n movers (1000 among 10 000).
Scene crowd_sensors(int n) {
    Scene s = crowd(n);
    const size_t movers = static_cast<size_t>(n);
    for (size_t i = 0; i < movers; i += 10) {
        SceneBody z = box(s.bodies[i].x, s.bodies[i].y - 20, 8);
        z.h = 32;
        z.sensor = z.immovable = true;
        s.bodies.push_back(z);
    }
    return s;
}

// crowd-resting: crowd stepped with resting contacts on, under which a
// stack of touching boxes stays put, as Box2D's stacks come to rest: the
// scene where resting groups of colliders can sleep (settle.hpp).
// crowd-resting ÷ crowd is what sleeping saves once the stacks rest.
Scene crowd_resting(int n) {
    Scene s = crowd(n);
    s.resting_contacts = true;
    return s;
}

// crowd-visitor: crowd-resting with one solid 8×8 box, no gravity, flying
// 2 px/frame along the stacks' tops 2 px above them (the bounce update
// turns it round at the walls): a player walking over a field of crates at
// rest. Every stack it comes within reach of wakes and is stepped, the rest
// sleep; crowd-visitor ÷ crowd-resting is what one mover among asleep
// groups costs.
Scene crowd_visitor(int n) {
    Scene s = crowd_resting(n);
    const int64_t floor_y = static_cast<int64_t>(s.rows - 1) * kTile;
    SceneBody v = box(kTile + 2, floor_y - 8 * 8 - 8 - 2, 8);
    v.vx = v.rvx = 2;
    v.solid = true;
    s.bodies.insert(s.bodies.begin() + n, v);  // a mover: before the pillars
    s.bounce = true;
    return s;
}

// rest: 8×8 gravity boxes (not solid) standing exactly on shelves of tiles,
// on-ground, vy 0: a frame changes nothing.
Scene rest(int n) {
    Scene s;
    int per_shelf = ceil_sqrt(4.0 * n);
    per_shelf += per_shelf % 2;
    const int shelves = (n + per_shelf - 1) / per_shelf;
    const int cols = per_shelf / 2 + 2, rows = 2 * shelves;
    Grid g(cols, rows);
    for (int r = 0; r < rows; ++r) g.set(0, r), g.set(cols - 1, r);
    for (int k = 0; k < shelves; ++k)
        for (int c = 0; c < cols; ++c) g.set(c, 2 * k + 1);
    for (int i = 0; i < n; ++i) {
        const int shelf = i / per_shelf;
        SceneBody b = box(kTile + 8 * (i % per_shelf), (2 * shelf + 1) * kTile - 8, 8);
        b.gravity = b.on_ground = true;
        s.bodies.push_back(b);
    }
    take(s, std::move(g));
    s.settle_box2d = true;
    return s;
}

// bullets: 4×4 bodies, no gravity, not solid, |v| in 20..60 px/frame in
// every direction, in an arena with a 1-tile border and short 1-tile-thick
// inner walls; the bounce update turns them round when a wall stops them.
Scene bullets(int n) {
    Scene s;
    const int margin = 48;
    int side = ceil_sqrt(n * 1.08);
    std::vector<std::pair<int, int>> spawn;
    for (;;) {
        const int cols = side + 2 * margin + 2;
        Grid g(cols, cols);
        g.walls();
        for (int r = 1; r < cols - 1; ++r)
            for (int c = 1; c < cols - 1; ++c)
                if ((r % 24 == 12 && c % 24 < 8) || (c % 24 == 12 && r % 24 >= 16)) g.set(c, r);
        spawn.clear();
        for (int r = 0; r < side && static_cast<int>(spawn.size()) < n; ++r)
            for (int c = 0; c < side && static_cast<int>(spawn.size()) < n; ++c)
                if (!g.get(margin + 1 + c, margin + 1 + r)) spawn.push_back({margin + 1 + c, margin + 1 + r});
        if (static_cast<int>(spawn.size()) == n) {
            take(s, std::move(g));
            break;
        }
        ++side;
    }
    uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&] {  // splitmix64: the same velocities on every platform
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return (z ^ (z >> 31)) >> 11;  // 53 bits
    };
    for (int i = 0; i < n; ++i) {
        SceneBody b = box(spawn[i].first * kTile + 6, spawn[i].second * kTile + 6, 4);
        const int64_t speed = 20 + static_cast<int64_t>(next() % 41);
        const double angle = static_cast<double>(next() % 3600) * (2 * M_PI / 3600);
        b.vx = std::llround(speed * std::cos(angle));
        b.vy = std::llround(speed * std::sin(angle));
        b.rvx = b.vx;
        b.rvy = b.vy;
        s.bodies.push_back(b);
    }
    s.bounce = true;
    s.bullets = true;
    return s;
}

// shots: a shooter's busy frame. N 4×4 shots (sensors in the category
// shot, colliding with enemy; bounce 1; no gravity; 2–4 px/frame in every
// direction, exact) fly about an open walled arena, 2 tiles apart at the
// start, among ten solid 24×24 enemies (bounce 1, 2 px/frame) they sense.
// Each shot carries the game's own keys (#:kind #:damage #:owner #:ttl) after
// the engine's, as an author writes them. shots has #:contacts? #t on every
// shot and enemy; shots-quiet is the same scene without it, so shots ÷
// shots-quiet is what the contact report costs. shots-author-first and
// shots-author-first-quiet put the game's keys before the engine's: the two
// ratios say whether where the keys sit decides what the report costs. The
// arena grows with N: every N sees the same density of shots.
Scene shots(int n, bool contacts, bool author_first) {
    Scene s;
    constexpr int kEnemies = 10;
    const int per_row = ceil_sqrt(n);
    const int rows_of_shots = (n + per_row - 1) / per_row;
    const int cols = 2 * per_row + 2, rows = 2 * rows_of_shots + 2;
    Grid g(cols, rows);
    g.walls();
    uint64_t state = 0x2545F4914F6CDD1Dull;
    auto next = [&] {  // splitmix64: the same velocities on every platform
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    };
    for (int i = 0; i < n; ++i) {
        SceneBody b = box((1 + 2 * (i % per_row)) * kTile + 6, (1 + 2 * (i / per_row)) * kTile + 6, 4);
        do {
            b.vx = static_cast<int64_t>(next() % 9) - 4;
            b.vy = static_cast<int64_t>(next() % 9) - 4;
        } while (std::max(std::abs(b.vx), std::abs(b.vy)) < 2);
        b.shot = b.sensor = b.bounce = b.author_keys = true;
        b.contacts = contacts;
        b.author_first = author_first;
        s.bodies.push_back(b);
    }
    for (int k = 0; k < kEnemies; ++k) {
        SceneBody e = box(kTile + 4 + (k * (cols - 4) * kTile) / kEnemies, kTile + 4 + (k * (rows - 4) * kTile) / kEnemies, 24);
        e.vx = k % 2 == 0 ? 2 : -2;
        e.vy = k % 3 == 0 ? 2 : -2;
        e.solid = e.target = e.bounce = true;
        e.contacts = contacts;
        s.bodies.push_back(e);
    }
    take(s, std::move(g));
    return s;
}

// platformer: the demo platformer's first 60×15 level, frozen in
// bench/maps/platformer-60x15.tmx (so figures stay comparable as the demo
// grows), with 12×16 gravity bots (not solid)
// dropped from the top rows, patrolling at vx ±2 and turning round at walls.
Scene platformer(int n) {
    Scene s;
    s.map_path = DS_BENCH_SOURCE_DIR "/bench/maps/platformer-60x15.tmx";
    const ds::Tilemap map = ds::load_tilemap(s.map_path);
    const ds::TileGrid grid = map.solid_grid();
    if (grid.tile_width() != grid.tile_height())
        throw std::runtime_error("platformer-60x15.tmx: tiles are not square");
    s.cols = grid.cols();
    s.rows = grid.rows();
    s.tile = grid.tile_width();
    s.solid.resize(static_cast<size_t>(s.cols) * s.rows);
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c)
            s.solid[static_cast<size_t>(r) * s.cols + c] =
                grid.solid(c + grid.origin_col(), r + grid.origin_row());
    for (int i = 0; i < n; ++i) {
        SceneBody b = box(16 + (static_cast<int64_t>(i) * 37) % 900, (static_cast<int64_t>(i) * 13) % 48, 12);
        b.h = 16;
        b.vx = b.rvx = (i % 2 == 0) ? 2 : -2;
        b.gravity = true;
        s.bodies.push_back(b);
    }
    s.bounce = true;
    return s;
}

// The rest scene must really be at rest: one native frame changes nothing.
void check_at_rest(const Scene& s) {
    ds::TileGrid grid(s.cols, s.rows, s.tile, s.tile, s.solid);
    ds::World world;
    world.grid = &grid;
    for (const SceneBody& sb : s.bodies) {
        ds::Body b;
        b.x = ds::Num::integer(static_cast<double>(sb.x));
        b.y = ds::Num::integer(static_cast<double>(sb.y));
        b.w = ds::Num::integer(static_cast<double>(sb.w));
        b.h = ds::Num::integer(static_cast<double>(sb.h));
        b.gravity = sb.gravity;
        b.on_ground = sb.on_ground;
        world.bodies.push_back(b);
    }
    const std::vector<ds::Body> before = world.bodies;
    ds::Frame frame;
    frame.step(world, {});
    for (size_t i = 0; i < before.size(); ++i)
        if (ds::changed_fields(before[i], world.bodies[i]) != 0)
            throw std::logic_error("rest scene: body " + std::to_string(i) + " is not at rest");
}

}  // namespace

const std::vector<std::string>& scene_names() {
    static const std::vector<std::string> names = {"rain", "crowd", "rest", "bullets", "platformer", "ramps",
                                                   "ramps-flat", "crowd-categories", "crowd-sensors", "crowd-resting", "crowd-visitor",
                                                   "shots", "shots-quiet", "shots-author-first",
                                                   "shots-author-first-quiet", "knobs",
                                                   "knobs-off"};
    return names;
}

bool is_scene(const std::string& name) {
    for (const auto& s : scene_names())
        if (s == name) return true;
    return false;
}

Scene make_scene(const std::string& name, int n) {
    Scene s;
    if (name == "rain") s = rain(n);
    else if (name == "crowd") s = crowd(n);
    else if (name == "rest") s = rest(n);
    else if (name == "bullets") s = bullets(n);
    else if (name == "platformer") s = platformer(n);
    else if (name == "ramps") s = ramps(n, false);
    else if (name == "ramps-flat") s = ramps(n, true);
    else if (name == "crowd-categories") s = crowd_categories(n);
    else if (name == "crowd-sensors") s = crowd_sensors(n);
    else if (name == "crowd-resting") s = crowd_resting(n);
    else if (name == "crowd-visitor") s = crowd_visitor(n);
    else if (name == "shots") s = shots(n, true, false);
    else if (name == "shots-quiet") s = shots(n, false, false);
    else if (name == "shots-author-first") s = shots(n, true, true);
    else if (name == "shots-author-first-quiet") s = shots(n, false, true);
    else if (name == "knobs") s = knobs(n, true);
    else if (name == "knobs-off") s = knobs(n, false);
    else throw std::invalid_argument("unknown scene " + name);
    s.name = name;
    s.n = n;
    if (name == "rest") check_at_rest(s);
    return s;
}

}  // namespace bench
