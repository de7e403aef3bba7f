// SPDX-License-Identifier: MIT
#include "tile_grid.hpp"

#include "detail/placed_shape.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace ds {

namespace {

constinit std::atomic<uint64_t> last_revision{0};

}  // namespace

uint64_t GridRevision::next() { return last_revision.fetch_add(1, std::memory_order_relaxed) + 1; }

TileGrid::TileGrid(int cols, int rows, int tile_w, int tile_h, std::vector<uint8_t> solid,
                   int64_t origin_col, int64_t origin_row)
    : cols_(cols), rows_(rows), tile_w_(tile_w), tile_h_(tile_h), origin_col_(origin_col),
      origin_row_(origin_row) {
    if (cols < 0 || rows < 0 || tile_w <= 0 || tile_h <= 0)
        throw std::invalid_argument("tile grid: sizes must be positive");
    if (solid.size() != static_cast<size_t>(cols) * static_cast<size_t>(rows))
        throw std::invalid_argument("tile grid: solid mask is not cols*rows long");
    for (uint8_t& c : solid)
        if (c != kEmptyCell && c != kOneWayCell) c = kSolidCell;
    solid_ = SharedCells<uint8_t>(solid);
}

TileGrid::TileGrid(TileGrid&& o) noexcept { *this = std::move(o); }

TileGrid& TileGrid::operator=(TileGrid&& o) noexcept {
    if (this == &o) return *this;
    cols_ = std::exchange(o.cols_, 0);
    rows_ = std::exchange(o.rows_, 0);
    tile_w_ = o.tile_w_;
    tile_h_ = o.tile_h_;
    origin_col_ = std::exchange(o.origin_col_, 0);
    origin_row_ = std::exchange(o.origin_row_, 0);
    solid_ = std::move(o.solid_);
    o.solid_.clear();
    shape_ids_ = std::move(o.shape_ids_);
    o.shape_ids_.clear();
    shapes_ = std::move(o.shapes_);
    o.shapes_.clear();
    geometry_ = std::move(o.geometry_);
    o.geometry_.clear();
    steepest_ = std::exchange(o.steepest_, 0.0);
    revision_.bump();
    o.revision_.bump();
    return *this;
}

void TileGrid::set_solid(int64_t col, int64_t row, bool solid) {
    set_cell(col, row, solid ? kSolidCell : kEmptyCell);
}

size_t TileGrid::edited_index(int64_t col, int64_t row, const char* what) const {
    const int64_t c = col - origin_col_, r = row - origin_row_;
    if (c < 0 || r < 0 || c >= cols_ || r >= rows_)
        throw std::out_of_range(std::string("tile grid: ") + what + " outside the grid");
    return index(col, row);
}

void TileGrid::set_cell(int64_t col, int64_t row, uint8_t kind) {
    solid_[edited_index(col, row, "set_cell")] = kind == kEmptyCell || kind == kOneWayCell ? kind : kSolidCell;
    revision_.bump();
}

void TileGrid::set_shape(int64_t col, int64_t row, const CellShape& shape) {
    const size_t i = edited_index(col, row, "set_shape");
    auto found = std::find(shapes_.begin(), shapes_.end(), shape);
    if (found == shapes_.end()) {
        if (shapes_.size() >= kMaxGridShapes)
            throw std::length_error("tile grid: more than " + std::to_string(kMaxGridShapes) + " distinct cell shapes");
        shapes_.push_back(shape);
        geometry_.push_back(ShapeGeometry::of(shape));
        steepest_ = std::max(steepest_, shape.steepness());
        found = std::prev(shapes_.end());
    }
    if (shape_ids_.empty()) shape_ids_.assign(solid_.size(), 0);
    shape_ids_[i] = static_cast<uint16_t>(found - shapes_.begin());
    solid_[i] = kShapedCell;
    revision_.bump();
}

bool TileGrid::solid_at(double x, double y) const {
    const int64_t c = cell_of(Num::flonum(x), tile_w_), r = cell_of(Num::flonum(y), tile_h_);
    if (solid(c, r)) return true;
    const CellShape* s = shape(c, r);
    return s && !s->one_way && shape_math::Placed(*s, c, r, *this).holds(x, y);
}

double CellShape::steepness() const {
    double k = 0;
    for (int i = 0; i < slants(); ++i) {
        const Slant l = slant(i);
        k = std::max(k, std::fabs(static_cast<double>(l.by - l.ay)) / static_cast<double>(l.bx - l.ax));
    }
    for (int i = 0; i < n_under; ++i) {
        const Slant& l = under[static_cast<size_t>(i)];
        k = std::max(k, std::fabs(static_cast<double>(l.by - l.ay)) / static_cast<double>(l.bx - l.ax));
    }
    return k;
}

namespace {

// Where along [x0, x1] a run of slants, left to right, is highest (`floor`:
// a top) or lowest (a bottom): x1 when every slant climbs that way
// rightwards, x0 when none does, else the right end of the last that does.
template <typename SlantAt>
int32_t apex_of(SlantAt slant, int n, bool floor, int32_t x0, int32_t x1) {
    // A floor's top climbs rightwards along a slant that rises (dy < 0), a
    // ceiling's bottom along one that falls (dy > 0).
    auto climbs = [&](const Slant& l) { return floor ? l.by < l.ay : l.by > l.ay; };
    int last_climbing = -1;
    for (int i = 0; i < n; ++i)
        if (climbs(slant(i))) last_climbing = i;
    if (last_climbing < 0) return x0;
    if (last_climbing == n - 1) return x1;
    return std::clamp(slant(last_climbing).bx, x0, x1);
}

}  // namespace

// The apex of a shape (semantics §12): where its surface over any span is
// read, clamped to the span.
int32_t CellShape::apex() const {
    return apex_of([&](int i) { return slant(i); }, slants(), cut == Cut::Floor, x0, x1);
}

// The same for a two-sided shape's underside (§12).
int32_t CellShape::under_apex() const {
    if (cut == Cut::Ceiling) return apex();
    return apex_of([&](int i) { return under[static_cast<size_t>(i)]; }, n_under, false, x0, x1);
}

}  // namespace ds
