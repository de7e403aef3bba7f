// SPDX-License-Identifier: MIT
// Cell ranges of a box and the TileGrid itself (semantics §4 "Tile cells of a box").
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>

#include "support.hpp"
#include "tile_grid.hpp"

using namespace dst;
using ds::CellRange;
using ds::cell_of;
using ds::cells_of;
using ds::TileGrid;

namespace {

bool range_is(CellRange r, int64_t first, int64_t last) {
    return r.first == first && r.last == last && !r.empty();
}

}  // namespace

TEST_SUITE("tile-grid") {

TEST_CASE("CellRange: the default range is empty; first == last is one cell") {
    CHECK(CellRange{}.empty());
    CHECK_FALSE((CellRange{3, 3}).empty());
    CHECK((CellRange{4, 3}).empty());
}

TEST_CASE("cells_of: a box inside one cell") {
    CellRange r = cells_of(I(0), I(16), 16);
    CHECK(r.first == 0);
    CHECK(r.last == 0);
    CHECK(range_is(cells_of(I(4), I(8), 16), 0, 0));
    CHECK(range_is(cells_of(I(15), I(1), 16), 0, 0));
    CHECK(range_is(cells_of(I(32), I(16), 16), 2, 2));
}

TEST_CASE("cells_of: touching an edge is not overlapping") {
    // [0, 16) ends exactly on column 1's left edge
    CHECK(range_is(cells_of(I(0), I(16), 16), 0, 0));
    // [16, 32) starts exactly on column 0's right edge
    CHECK(range_is(cells_of(I(16), I(16), 16), 1, 1));
    // one pixel more on either side reaches the neighbour
    CHECK(range_is(cells_of(I(1), I(16), 16), 0, 1));
    CHECK(range_is(cells_of(I(15), I(16), 16), 0, 1));
    CHECK(range_is(cells_of(I(0), I(17), 16), 0, 1));
    // a 48 px box on a boundary covers exactly three cells
    CHECK(range_is(cells_of(I(16), I(48), 16), 1, 3));
}

TEST_CASE("cells_of: flonum positions") {
    CHECK(range_is(cells_of(F(15.5), F(0.5), 16), 0, 0));
    CHECK(range_is(cells_of(F(15.5), F(1.0), 16), 0, 1));
    CHECK(range_is(cells_of(F(16.0), F(16.0), 16), 1, 1));
    CHECK(range_is(cells_of(F(0.25), I(16), 16), 0, 1));
    CHECK(range_is(cells_of(I(0), F(15.75), 16), 0, 0));
}

TEST_CASE("cells_of: zero and negative sizes overlap nothing") {
    CHECK(cells_of(I(0), I(0), 16).empty());
    CHECK(cells_of(I(8), I(0), 16).empty());
    CHECK(cells_of(I(-8), I(0), 16).empty());
    CHECK(cells_of(F(8.5), F(0.0), 16).empty());
    CHECK(cells_of(I(8), I(-4), 16).empty());
    CHECK(cells_of(F(8.0), F(-0.5), 16).empty());
}

TEST_CASE("cells_of: negative coordinates, exact and flonum") {
    // x = -1, w = 1 is the last pixel of column -1 and nothing of column 0
    CHECK(range_is(cells_of(I(-1), I(1), 16), -1, -1));
    CHECK(range_is(cells_of(F(-1.0), F(1.0), 16), -1, -1));
    CHECK(range_is(cells_of(F(-0.5), F(0.5), 16), -1, -1));
    CHECK(range_is(cells_of(I(-1), I(2), 16), -1, 0));
    CHECK(range_is(cells_of(I(-16), I(16), 16), -1, -1));
    CHECK(range_is(cells_of(I(-17), I(16), 16), -2, -1));
    CHECK(range_is(cells_of(I(-32), I(32), 16), -2, -1));
    CHECK(range_is(cells_of(I(-20), I(8), 16), -2, -1));
    CHECK(range_is(cells_of(F(-16.5), F(0.5), 16), -2, -2));
    CHECK(range_is(cells_of(F(-20.0), F(8.0), 16), -2, -1));
}

TEST_CASE("cells_of: tiles other than 16 px") {
    CHECK(range_is(cells_of(I(12), I(8), 8), 1, 2));
    CHECK(range_is(cells_of(I(12), I(4), 8), 1, 1));
    CHECK(range_is(cells_of(I(-3), I(3), 8), -1, -1));
    CHECK(range_is(cells_of(I(10), I(1), 1), 10, 10));
    CHECK(range_is(cells_of(I(0), I(100), 32), 0, 3));
}

TEST_CASE("cells_of: huge coordinates") {
    // 1e9 exact: 1e9 / 16 = 62,500,000 exactly
    CHECK(range_is(cells_of(I(1e9), I(16), 16), 62500000, 62500000));
    CHECK(range_is(cells_of(I(1e9 + 1), I(16), 16), 62500000, 62500001));
    CHECK(range_is(cells_of(I(-1e9), I(16), 16), -62500000, -62500000));
    CHECK(range_is(cells_of(I(-1e9 - 1), I(1), 16), -62500001, -62500001));
    // 1e12 flonum
    CHECK(range_is(cells_of(F(1e12), F(16.0), 16), 62500000000LL, 62500000000LL));
    CHECK(range_is(cells_of(F(1e12 + 8), F(16.0), 16), 62500000000LL, 62500000001LL));
    CHECK(range_is(cells_of(F(-1e12), F(1.0), 16), -62500000000LL, -62500000000LL));
    // the largest exact integers: 2^53 - 1 is the last pixel of column 2^49 - 1
    const double top = ds::kMaxExact - 1;
    CHECK(range_is(cells_of(I(top), I(1), 16), (1LL << 49) - 1, (1LL << 49) - 1));
    CHECK(range_is(cells_of(I(ds::kMaxExact - 32), I(16), 16), (1LL << 49) - 2,
                   (1LL << 49) - 2));
}

TEST_CASE("cell_of: floor of pos / tile") {
    CHECK(cell_of(I(0), 16) == 0);
    CHECK(cell_of(I(15), 16) == 0);
    CHECK(cell_of(I(16), 16) == 1);
    CHECK(cell_of(I(-1), 16) == -1);
    CHECK(cell_of(I(-16), 16) == -1);
    CHECK(cell_of(I(-17), 16) == -2);
    CHECK(cell_of(F(15.999), 16) == 0);
    CHECK(cell_of(F(16.0), 16) == 1);
    CHECK(cell_of(F(-0.5), 16) == -1);
    CHECK(cell_of(F(-0.0), 16) == 0);
    CHECK(cell_of(I(20), 8) == 2);
    CHECK(cell_of(I(1e9), 16) == 62500000);
    CHECK(cell_of(F(1e12), 16) == 62500000000LL);
    CHECK(cell_of(F(-1e12), 16) == -62500000000LL);
}

TEST_CASE("cell_of and cells_of: flonums on both sides of 2^52 cells") {
    // Below 2^52 a quotient is truncated and corrected by one; from 2^52 on
    // floor/ceil and the clamp take it. Both sides give the same cells.
    const double near = 0x1p52 * 16;  // pos / 16 == 2^52
    CHECK(cell_of(F(near - 16), 16) == (1LL << 52) - 1);
    CHECK(cell_of(F(near), 16) == 1LL << 52);
    CHECK(cell_of(F(-near + 16), 16) == -(1LL << 52) + 1);
    CHECK(cell_of(F(-near), 16) == -(1LL << 52));
    CHECK(cell_of(F(-8.0), 16) == -1);
    CHECK(cell_of(F(-16.0), 16) == -1);
    CHECK(cell_of(F(-16.5), 16) == -2);
    CHECK(range_is(cells_of(F(near - 32), F(16.0), 16), (1LL << 52) - 2, (1LL << 52) - 2));
    CHECK(range_is(cells_of(F(-near), F(8.0), 16), -(1LL << 52), -(1LL << 52)));
    // beyond int64 the clamp holds
    CHECK(cell_of(F(1e300), 16) == static_cast<int64_t>(ds::kCellIndexLimit));
    CHECK(cell_of(F(-1e300), 16) == static_cast<int64_t>(-ds::kCellIndexLimit));
    // just below 2^52 px a flonum is still shifted; at 2^52 it is divided
    const double edge = 0x1p52;
    CHECK(cell_of(F(edge - 0.5), 16) == (1LL << 48) - 1);
    CHECK(cell_of(F(-edge + 0.5), 16) == -(1LL << 48));
    CHECK(cell_of(F(edge), 16) == 1LL << 48);
    CHECK(range_is(cells_of(F(edge - 16.5), F(0.25), 16), (1LL << 48) - 2, (1LL << 48) - 2));
    CHECK(range_is(cells_of(F(edge - 16.5), F(0.5), 16), (1LL << 48) - 2, (1LL << 48) - 2));  // touches the next
    CHECK(range_is(cells_of(F(edge - 16.5), F(1.0), 16), (1LL << 48) - 2, (1LL << 48) - 1));
    CHECK(range_is(cells_of(F(-edge + 0.5), F(16.0), 16), -(1LL << 48), -(1LL << 48) + 1));
    CHECK(range_is(cells_of(F(edge), F(16.0), 16), 1LL << 48, 1LL << 48));
    CHECK(range_is(cells_of(F(-0.25), F(0.25), 8), -1, -1));
    CHECK(range_is(cells_of(F(-0.25), F(0.5), 8), -1, 0));
    // cells of 24 px: a quotient that is not a power-of-two scaling
    CHECK(cell_of(F(-0.25), 24) == -1);
    CHECK(cell_of(F(47.75), 24) == 1);
    CHECK(range_is(cells_of(F(23.5), F(24.5), 24), 0, 1));
    CHECK(range_is(cells_of(F(-24.0), F(24.0), 24), -1, -1));
}

TEST_CASE("TileGrid: sizes and the row-major solid mask") {
    // . # . .
    // # . . #
    TileGrid g(4, 2, 16, 8, {0, 1, 0, 0, 1, 0, 0, 1});
    CHECK(g.cols() == 4);
    CHECK(g.rows() == 2);
    CHECK(g.tile_width() == 16);
    CHECK(g.tile_height() == 8);
    CHECK(g.origin_col() == 0);
    CHECK(g.origin_row() == 0);
    CHECK_FALSE(g.solid(0, 0));
    CHECK(g.solid(1, 0));
    CHECK_FALSE(g.solid(2, 0));
    CHECK_FALSE(g.solid(3, 0));
    CHECK(g.solid(0, 1));
    CHECK_FALSE(g.solid(1, 1));
    CHECK_FALSE(g.solid(2, 1));
    CHECK(g.solid(3, 1));
}

TEST_CASE("TileGrid: cells outside the grid are empty") {
    TileGrid g = grid({"####", "####"});
    CHECK(g.solid(0, 0));
    CHECK(g.solid(3, 1));
    CHECK_FALSE(g.solid(-1, 0));
    CHECK_FALSE(g.solid(0, -1));
    CHECK_FALSE(g.solid(4, 0));
    CHECK_FALSE(g.solid(0, 2));
    CHECK_FALSE(g.solid(4, 2));
    CHECK_FALSE(g.solid(62500000000LL, 0));
    CHECK_FALSE(g.solid(-62500000000LL, -62500000000LL));
    TileGrid empty;
    CHECK(empty.cols() == 0);
    CHECK(empty.rows() == 0);
    CHECK_FALSE(empty.solid(0, 0));
}

TEST_CASE("TileGrid: an origin offset places solid[0] at a negative cell") {
    // 2 × 2 cells whose first cell is map cell (-2, -1)
    TileGrid g(2, 2, 16, 16, {1, 0, 0, 1}, -2, -1);
    CHECK(g.origin_col() == -2);
    CHECK(g.origin_row() == -1);
    CHECK(g.solid(-2, -1));
    CHECK_FALSE(g.solid(-1, -1));
    CHECK_FALSE(g.solid(-2, 0));
    CHECK(g.solid(-1, 0));
    CHECK_FALSE(g.solid(0, 0));   // outside now
    CHECK_FALSE(g.solid(0, 1));
    CHECK_FALSE(g.solid(-3, -1));
}

TEST_CASE("TileGrid: clip_cols / clip_rows keep the part inside the grid") {
    TileGrid g = grid({"....", "....", "...."});
    CHECK(range_is(g.clip_cols({-5, 10}), 0, 3));
    CHECK(range_is(g.clip_cols({1, 2}), 1, 2));
    CHECK(range_is(g.clip_cols({3, 100}), 3, 3));
    CHECK(g.clip_cols({4, 10}).empty());
    CHECK(g.clip_cols({-10, -1}).empty());
    CHECK(g.clip_cols(CellRange{}).empty());
    CHECK(range_is(g.clip_rows({-5, 10}), 0, 2));
    CHECK(g.clip_rows({3, 3}).empty());
    CHECK(range_is(g.clip_cols({-4000000000000000000LL, 4000000000000000000LL}), 0, 3));

    TileGrid off(2, 2, 16, 16, {0, 0, 0, 0}, -2, 5);
    CHECK(range_is(off.clip_cols({-10, 10}), -2, -1));
    CHECK(range_is(off.clip_rows({0, 5}), 5, 5));
    CHECK(off.clip_rows({0, 4}).empty());
}

TEST_CASE("TileGrid: a mask of the wrong length or a non-positive tile is rejected") {
    CHECK_THROWS_AS(TileGrid(2, 2, 16, 16, {1, 0, 0}), std::invalid_argument);
    CHECK_THROWS_AS(TileGrid(2, 2, 0, 16, {1, 0, 0, 1}), std::invalid_argument);
    CHECK_THROWS_AS(TileGrid(2, 2, 16, -16, {1, 0, 0, 1}), std::invalid_argument);
    CHECK_NOTHROW(TileGrid(0, 0, 16, 16, {}));
}

TEST_CASE("TileGrid: set_solid edits a cell in map coordinates and bumps the revision") {
    TileGrid g(2, 2, 16, 16, {0, 0, 0, 1}, -1, 3);
    const uint64_t r0 = g.revision();
    CHECK(r0 != 0);
    g.set_solid(-1, 3, true);
    CHECK(g.solid(-1, 3));
    const uint64_t r1 = g.revision();
    CHECK(r1 != r0);
    g.set_solid(0, 4, false);
    CHECK_FALSE(g.solid(0, 4));
    CHECK(g.revision() != r1);
    // Every edit bumps it, even one that leaves the cell as it was.
    const uint64_t r2 = g.revision();
    g.set_solid(0, 4, false);
    CHECK(g.revision() != r2);
    // Outside the grid: nothing to edit.
    const uint64_t r3 = g.revision();
    CHECK_THROWS_AS(g.set_solid(1, 3, true), std::out_of_range);
    CHECK_THROWS_AS(g.set_solid(-2, 3, false), std::out_of_range);
    CHECK_THROWS_AS(g.set_solid(0, 5, true), std::out_of_range);
    CHECK(g.revision() == r3);
}

TEST_CASE("TileGrid: no two grids share a revision, whatever their address") {
    TileGrid a = grid({"##"});
    TileGrid b = grid({"##"});
    CHECK(a.revision() != b.revision());
    // A copy has the same cells and a revision of its own; assigning gives
    // the target a new one.
    TileGrid c = a;
    CHECK(c.solid(1, 0));
    CHECK(c.revision() != a.revision());
    const uint64_t before = b.revision();
    b = a;
    CHECK(b.revision() != before);
    CHECK(b.revision() != a.revision());
    // Moving: the target gets a new revision, the source is left empty with
    // one of its own.
    const uint64_t ra = a.revision(), rc = c.revision();
    TileGrid d = std::move(a);
    CHECK(d.solid(0, 0));
    CHECK(d.revision() != ra);
    CHECK(a.cols() == 0);
    CHECK(a.rows() == 0);
    CHECK_FALSE(a.solid(0, 0));
    CHECK(a.revision() != ra);
    c = std::move(d);
    CHECK(c.solid(1, 0));
    CHECK(c.revision() != rc);
    CHECK(d.cols() == 0);
    // A new grid built in the very storage of an old one: same address, new
    // revision.
    alignas(TileGrid) unsigned char storage[sizeof(TileGrid)];
    auto* first = new (storage) TileGrid(grid({"#."}));
    const uint64_t r_first = first->revision();
    std::destroy_at(first);
    auto* second = new (storage) TileGrid(grid({"#."}));
    CHECK(static_cast<void*>(second) == static_cast<void*>(first));
    CHECK(second->revision() != r_first);
    std::destroy_at(second);
}

TEST_CASE("cells of exact coordinates far past int64 do not overflow") {
    const auto r = ds::cells_of(ds::Num::integer(1e300), ds::Num::integer(16), 16);
    CHECK(r.first > (1LL << 61));  // clamped: far outside any map
    CHECK(ds::cell_of(ds::Num::integer(-1e300), 16) < -(1LL << 60));
    // power-of-two tiles take the shift path: floors negatives like floor_div
    CHECK(ds::cells_of(ds::Num::integer(-17), ds::Num::integer(2), 16).first == -2);
    CHECK(ds::cells_of(ds::Num::integer(-17), ds::Num::integer(2), 16).last == -1);
    CHECK(ds::cells_of(ds::Num::integer(-17), ds::Num::integer(1), 16).last == -2);
    CHECK(ds::cell_of(ds::Num::integer(-16), 16) == -1);
    CHECK(ds::cell_of(ds::Num::integer(-15), 16) == -1);
    CHECK(ds::cells_of(ds::Num::integer(-17), ds::Num::integer(2), 12).first == -2);
}

}  // TEST_SUITE
