// SPDX-License-Identifier: MIT
// The solid-cell grid physics reads: which cells of a tile map block bodies.
// Built from a loaded Tiled map or directly from a gid vector; knows nothing
// of XML. Cells outside the grid are empty. A grid is known by its revision,
// never by its address: whatever is kept per map (settled bodies, above
// all) compares revisions.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "cell_shape.hpp"
#include "constants.hpp"
#include "number.hpp"
#include "shared_cells.hpp"
#include "export.hpp"

namespace ds {

// A run of cell indices along one axis, [first, last] with both ends
// included; empty when last < first. (A 2-D box of cells is detail/cell_hash.hpp's
// CellBox.)
struct CellRange {
    int64_t first = 0;
    int64_t last = -1;
    bool empty() const { return last < first; }
};

// The cells along one axis that the interval [pos, pos+size) overlaps, with
// cells of `tile` pixels: ⌊pos/tile⌋ … ⌈(pos+size)/tile⌉−1. Touching a cell
// edge is not overlapping; size ≤ 0 overlaps nothing. Exact positions use
// integer arithmetic so huge coordinates do not lose cells.
[[gnu::always_inline]] inline CellRange cells_of(Num pos, Num size, int tile);
// ⌊pos/tile⌋ on its own (the ground probe's row).
[[gnu::always_inline]] inline int64_t cell_of(Num pos, int tile);

// A grid revision: drawn from one process-wide counter whenever a grid is
// made, copied, assigned or edited, so no two states of any grids in the
// process share one — not even a new grid built where an old one was. Never 0
// (callers keep 0 for "no grid").
// What a grid's cell holds: nothing, a whole solid or one-way block, or a
// shape (semantics §12) kept in the grid's table of shapes.
constexpr uint8_t kEmptyCell = 0, kSolidCell = 1, kOneWayCell = 2, kShapedCell = 3;

class DOWNSTROKE_API GridRevision {
public:
    GridRevision() : n_(next()) {}
    GridRevision(const GridRevision&) : n_(next()) {}
    GridRevision& operator=(const GridRevision&) {
        n_ = next();
        return *this;
    }
    void bump() { n_ = next(); }
    uint64_t value() const { return n_; }

private:
    static uint64_t next();
    uint64_t n_;
};

class DOWNSTROKE_API TileGrid {
public:
    TileGrid() = default;
    // cols × rows cells of tile_w × tile_h px; solid is row-major, cols*rows
    // long: 0 empty, kOneWayCell a one-way platform, anything else solid.
    // origin_col/row is the map cell of solid[0] (negative for infinite maps
    // whose chunks start left of or above the origin).
    TileGrid(int cols, int rows, int tile_w, int tile_h, std::vector<uint8_t> solid,
             int64_t origin_col = 0, int64_t origin_row = 0);
    // A copy is a grid of its own: same cells (sharing their chunks until
    // either grid is edited), a new revision. A moved-from
    // grid is left empty (0 × 0), with a new revision too.
    TileGrid(const TileGrid&) = default;
    TileGrid& operator=(const TileGrid&) = default;
    TileGrid(TileGrid&& o) noexcept;
    TileGrid& operator=(TileGrid&& o) noexcept;

    // This state of the grid (see GridRevision): every edit changes it.
    uint64_t revision() const { return revision_.value(); }

    // Makes a cell solid or empty (map cells, as solid() takes them) and
    // bumps the revision. The grid does not grow: a cell outside it is
    // std::out_of_range.
    void set_solid(int64_t col, int64_t row, bool solid);
    // The same for any whole kind of cell (kEmptyCell, kSolidCell, kOneWayCell).
    void set_cell(int64_t col, int64_t row, uint8_t kind);
    // Gives a cell a shape (kShapedCell), added to the grid's table unless an
    // equal one is there; std::length_error past kMaxGridShapes distinct shapes.
    void set_shape(int64_t col, int64_t row, const CellShape& shape);

    int cols() const { return cols_; }
    int rows() const { return rows_; }
    int tile_width() const { return tile_w_; }
    int tile_height() const { return tile_h_; }
    int64_t origin_col() const { return origin_col_; }
    int64_t origin_row() const { return origin_row_; }

    // What a cell holds: kEmptyCell (also outside the grid), kSolidCell,
    // kOneWayCell or kShapedCell. One lookup, for loops that test every kind.
    uint8_t cell(int64_t col, int64_t row) const {
        col -= origin_col_;
        row -= origin_row_;
        if (col < 0 || row < 0 || col >= cols_ || row >= rows_) return kEmptyCell;
        return solid_[static_cast<size_t>(row * cols_ + col)];
    }
    // cell() for a cell known to lie in the grid, as every cell of ranges
    // clip_cols and clip_rows gave does: the tile steps' loops read a few
    // per body, and the bounds test cost as much as the read.
    uint8_t cell_in(int64_t col, int64_t row) const { return solid_[index(col, row)]; }
    // A whole solid block (a shaped cell is not: see shape()).
    bool solid(int64_t col, int64_t row) const { return cell(col, row) == kSolidCell; }
    // A one-way platform (semantics §9): it stops bodies only from above.
    bool one_way(int64_t col, int64_t row) const { return cell(col, row) == kOneWayCell; }
    // A shaped cell's shape, or nullptr for any other cell.
    const CellShape* shape(int64_t col, int64_t row) const {
        if (cell(col, row) != kShapedCell) return nullptr;
        return &shapes_[shape_ids_[index(col, row)]];
    }
    // For a cell known to be kShapedCell (cell() said so): its shape's place
    // in the grid's table, which shape_at and geometry_at read.
    uint16_t shape_id_in(int64_t col, int64_t row) const { return shape_ids_[index(col, row)]; }
    const CellShape& shape_at(uint16_t id) const { return shapes_[id]; }
    const ShapeGeometry& geometry_at(uint16_t id) const { return geometry_[id]; }
    // Whether the world point (x, y) lies in a solid part of the grid: a
    // whole solid cell, or inside a solid shape (one-way parts are not
    // solid to queries, semantics §8).
    bool solid_at(double x, double y) const;
    // Whether any cell has ever had a shape: a grid without shapes takes
    // none of the shape rules' paths, and costs what it did before them.
    bool has_shapes() const { return !shapes_.empty(); }
    // The steepest ramp among the shapes the grid has held (|dy/dx|; 0 for
    // none): how far a body walking at vx px/frame may snap down (§12).
    double steepest_ramp() const { return steepest_; }
    std::span<const CellShape> shape_table() const { return shapes_; }
    // The doubles of a shape this grid's shape() gave (and of no other).
    const ShapeGeometry& geometry(const CellShape& s) const {
        return geometry_[static_cast<size_t>(&s - shapes_.data())];
    }

    // The part of a column (row) range that lies inside the grid: physics
    // never walks cells that cannot be solid, however large the box or move.
    CellRange clip_cols(CellRange r) const { return clip(r, origin_col_, cols_); }
    CellRange clip_rows(CellRange r) const { return clip(r, origin_row_, rows_); }

private:
    // Inline: the tile steps clip a few ranges per body.
    static CellRange clip(CellRange r, int64_t origin, int count) {
        return {std::max(r.first, origin), std::min(r.last, origin + count - 1)};
    }
    // A cell's index for an edit, or std::out_of_range naming `what`.
    size_t edited_index(int64_t col, int64_t row, const char* what) const;
    size_t index(int64_t col, int64_t row) const {
        return static_cast<size_t>((row - origin_row_) * cols_ + (col - origin_col_));
    }

    int cols_ = 0, rows_ = 0, tile_w_ = 1, tile_h_ = 1;
    int64_t origin_col_ = 0, origin_row_ = 0;
    SharedCells<uint8_t> solid_;  // row-major, one kind per cell
    // For kShapedCell cells, the index of their shape in shapes_; empty (no
    // memory at all) until a cell gets a shape.
    SharedCells<uint16_t> shape_ids_;
    std::vector<CellShape> shapes_;  // distinct, in the order first met
    std::vector<ShapeGeometry> geometry_;  // shapes_[i]'s doubles
    double steepest_ = 0;
    GridRevision revision_;
};

// The revision of a map, or 0 for none.
inline uint64_t revision_of(const TileGrid* grid) { return grid ? grid->revision() : 0; }

// Defined here so the tile steps, which ask for a few per body, inline them.
namespace cell_math {

// ⌊a/b⌋ and ⌈a/b⌉ for b > 0 in integers: exact for every int64.
inline int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && (a < 0)); }
inline int64_t ceil_div(int64_t a, int64_t b) { return a / b + ((a % b != 0) && (a > 0)); }

// ⌊q⌋ and ⌈q⌉ as cell indices, clamped to ±kCellIndexLimit (beyond it
// the conversion is undefined, and such cells lie outside any grid).
// Truncating and correcting by one is exact for every clamped q: without
// SSE4.1's roundsd, std::floor is a libm call, and a body on a 1:2 ramp
// stays a flonum from its first half pixel on (semantics §12), so the tile
// steps ask for several per body. The hashed grids use the same.
inline int64_t floor_cell(double q) {
    const double c = std::clamp(q, -kCellIndexLimit, kCellIndexLimit);
    const auto t = static_cast<int64_t>(c);
    return t - (c < static_cast<double>(t));
}
inline int64_t ceil_cell(double q) { return -floor_cell(-q); }

// Tiles are nearly always a power of two wide: a shift then does the
// division (an arithmetic shift floors negatives too).
inline bool power_of_two(int tile) { return (tile & (tile - 1)) == 0; }

// Exact and small enough for int64 arithmetic without overflow (exact
// integers can be any size; past 2^61 the double path, which clamps, is
// exact enough: such cells lie outside any map).
inline bool integral(Num n) { return n.exact && std::fabs(n.v) < 2.3e18; }

}  // namespace cell_math

// Always inlined: the tile steps ask for a few per body, and a call costs
// more than the arithmetic (measured: 12% of a frame of ramps out of line).
[[gnu::always_inline]] inline CellRange cells_of(Num pos, Num size, int tile) {
    using namespace cell_math;
    if (!(size.v > 0)) return {};
    if (integral(pos) && integral(size)) {
        const auto p = static_cast<int64_t>(pos.v), s = static_cast<int64_t>(size.v);
        if (power_of_two(tile)) {
            const int k = std::countr_zero(static_cast<unsigned>(tile));
            return {p >> k, ((p + s + tile - 1) >> k) - 1};
        }
        return {floor_div(p, tile), ceil_div(p + s, tile) - 1};
    }
    // A flonum box (a body on a 1:2 ramp stays one from its first half
    // pixel on): on power-of-two tiles, ⌊v⌋ shifted is ⌊v/tile⌋, with no
    // division; the same cells as dividing (below, with the same rounded
    // far edge) while the position and size stay below 2^52.
    if (power_of_two(tile) && std::fabs(pos.v) < 0x1p52 && size.v < 0x1p52) {
        const int k = std::countr_zero(static_cast<unsigned>(tile));
        const double end = pos.v + size.v;
        const auto t = static_cast<int64_t>(pos.v), e = static_cast<int64_t>(end);
        const int64_t lo = t - (pos.v < static_cast<double>(t)), hi = e + (end > static_cast<double>(e));
        return {lo >> k, ((hi + tile - 1) >> k) - 1};
    }
    return {floor_cell(pos.v / tile), ceil_cell((pos.v + size.v) / tile) - 1};
}

[[gnu::always_inline]] inline int64_t cell_of(Num pos, int tile) {
    using namespace cell_math;
    if (integral(pos)) {
        const auto p = static_cast<int64_t>(pos.v);
        return power_of_two(tile) ? p >> std::countr_zero(static_cast<unsigned>(tile)) : floor_div(p, tile);
    }
    if (power_of_two(tile) && std::fabs(pos.v) < 0x1p52) {  // as cells_of does
        const auto t = static_cast<int64_t>(pos.v);
        return (t - (pos.v < static_cast<double>(t))) >> std::countr_zero(static_cast<unsigned>(tile));
    }
    return floor_cell(pos.v / tile);
}

}  // namespace ds
