// SPDX-License-Identifier: MIT
// Tiles that change: SharedCells' copy-on-write chunks, set_tile editing a
// map and its grid in place, and whole frames (ds::Frame::step, with the
// settling tracker on and off) seeing every edit on the next frame.
#include <string>
#include <vector>

#include "frame.hpp"
#include "shared_cells.hpp"
#include "support.hpp"
#include "tilemap/tilemap.hpp"

using namespace dst;
using ds::SharedCells;
using ds::Tilemap;
using ds::TileGrid;

namespace {

constexpr size_t kChunk = SharedCells<uint32_t>::kChunk;

// 4 × 4 cells of 16 px, gid 1 solid, floor in row 3 (with a hole at (1, 3)).
Tilemap floor_map(bool hole) {
    return ds::make_tilemap(4, 4, 16, 16, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, hole ? 0u : 1u, 1, 1}, {1});
}
Tilemap holed_floor() { return floor_map(true); }

// A world whose first body is `b` over `grid`; with `crowd`, three bodies
// drifting sideways in the air join it, so that fewer than half the bodies
// can settle and the frame does not track settling.
ds::World world_of(const Body& b, const TileGrid& grid, bool crowd) {
    ds::World w;
    w.bodies.push_back(b);
    for (int k = 0; crowd && k < 3; ++k) {
        Body drifter = box(0, -100 - 20 * k, 4, 4);
        drifter.vx = I(1);
        w.bodies.push_back(drifter);
    }
    w.grid = &grid;
    return w;
}

Body sitter(double x, double y) {
    Body b = box(x, y, 16, 16);
    b.gravity = true;
    b.on_ground = true;
    return b;
}

// Bodies whose gravity step ran in the last frame: 0 when the sitter slept.
uint64_t fell_through_gravity(const ds::Frame& f) { return f.stats().step[ds::kStepGravity].processed; }

}  // namespace

TEST_SUITE("tile-edit") {

TEST_CASE("SharedCells: a copy shares every chunk until a cell is written, then only that chunk is its own") {
    std::vector<uint32_t> cells(3 * kChunk + 5, 0);
    cells[7] = 3;
    cells[2 * kChunk + 1] = 9;
    const SharedCells<uint32_t> a(cells);
    SharedCells<uint32_t> b = a;
    b[kChunk + 2] = 4;
    CHECK(a[kChunk + 2] == 0);
    CHECK(b[kChunk + 2] == 4);
    CHECK(b.shares_chunk(a, 0));
    CHECK_FALSE(b.shares_chunk(a, kChunk));
    CHECK(b.shares_chunk(a, 2 * kChunk));
    CHECK(b.shares_chunk(a, 3 * kChunk));
    CHECK(a == cells);
    cells[kChunk + 2] = 4;
    CHECK(b.to_vector() == cells);
    CHECK(b.size() == 3 * kChunk + 5);
}

TEST_CASE("SharedCells: empty chunks are one chunk; writing one leaves the others empty") {
    SharedCells<uint8_t> z(std::vector<uint8_t>(2 * kChunk, 0));
    CHECK(z.shares_chunk(z, 0));
    z[3] = 1;
    CHECK(z[3] == 1);
    CHECK(z[kChunk + 3] == 0);
    SharedCells<uint8_t> filled(kChunk + 1, 2);
    filled[kChunk] = 0;
    CHECK(filled[0] == 2);
    CHECK(filled[kChunk] == 0);
}

TEST_CASE("a copied map and grid keep their cells when the copy is edited") {
    const Tilemap map = holed_floor();
    const TileGrid grid = map.solid_grid();
    Tilemap edited = map;
    TileGrid edited_grid = grid;
    ds::set_tile(edited, edited_grid, 0, 1, 3, 1);
    CHECK(map.layers[0].raw_gid(1, 3) == 0);
    CHECK_FALSE(grid.solid(1, 3));
    CHECK(edited.layers[0].raw_gid(1, 3) == 1);
    CHECK(edited_grid.solid(1, 3));
    CHECK(edited_grid.revision() != grid.revision());
}

TEST_CASE("set_tile: a one-way gid, and refusals that leave map and grid untouched") {
    Tilemap map = ds::make_tilemap(2, 2, 16, 16, {0, 0, 1, 1}, {1}, ds::kMaxMapCells, {2});
    TileGrid grid = map.solid_grid();
    ds::set_tile(map, grid, 0, 0, 0, 2);
    CHECK(grid.one_way(0, 0));
    const uint64_t rev = grid.revision();
    CHECK_THROWS_AS(ds::set_tile(map, grid, 0, 2, 0, 1), std::out_of_range);
    CHECK_THROWS_AS(ds::set_tile(map, grid, 1, 0, 0, 1), std::out_of_range);
    CHECK(grid.revision() == rev);
    Tilemap level = ds::load_tilemap(DS_TEST_DATA "/maps/level_csv.tmx");
    TileGrid level_grid = level.solid_grid();
    const uint32_t before = level.layers[0].raw_gid(0, 0);
    CHECK_THROWS_WITH_AS(ds::set_tile(level, level_grid, 0, 0, 0, 999),
                         "set_tile: gid 999 belongs to none of the map's tilesets", std::invalid_argument);
    CHECK(level.layers[0].raw_gid(0, 0) == before);
}

TEST_CASE("a body resting on a tile removed between frames falls on the next frame, tracking or not") {
    for (const bool crowd : {false, true}) {
        CAPTURE(crowd);
        Tilemap map = floor_map(false);
        TileGrid grid = map.solid_grid();
        ds::World w = world_of(sitter(16, 32), grid, crowd);
        ds::Frame f;
        for (int k = 0; k < 3; ++k) f.step(w, {});
        CHECK(fell_through_gravity(f) == (crowd ? 1 : 0));  // asleep only while tracking
        REQUIRE(same_body(w.bodies[0], sitter(16, 32)));
        ds::set_tile(map, grid, 0, 1, 3, 0);
        f.step(w, {});
        CHECK_EXACT(w.bodies[0].y, 33);
        CHECK_EXACT(w.bodies[0].vy, 1);
        CHECK_FALSE(w.bodies[0].on_ground);
    }
}

TEST_CASE("a body in the air over a cell made solid lands on it, tracking or not") {
    for (const bool crowd : {false, true}) {
        CAPTURE(crowd);
        Tilemap map = holed_floor();
        TileGrid grid = map.solid_grid();
        Body faller = sitter(16, 0);
        faller.on_ground = false;
        ds::World w = world_of(faller, grid, crowd);
        ds::Frame f;
        f.step(w, {});
        f.step(w, {});
        CHECK_EXACT(w.bodies[0].y, 3);  // 1 + 2: nothing below yet
        ds::set_tile(map, grid, 0, 1, 3, 1);
        for (int k = 0; k < 12; ++k) f.step(w, {});
        CHECK_EXACT(w.bodies[0].y, 32);
        CHECK_EXACT(w.bodies[0].vy, 0);
        CHECK(w.bodies[0].on_ground);
        for (int k = 0; k < 3; ++k) f.step(w, {});
        CHECK(fell_through_gravity(f) == (crowd ? 1 : 0));  // landed, then asleep while tracking
    }
}

}  // TEST_SUITE
