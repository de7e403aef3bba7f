#include "tile_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace ds {

TileGrid::TileGrid(int cols, int rows, int tile_w, int tile_h, std::vector<uint8_t> solid,
                   int64_t origin_col, int64_t origin_row)
    : cols_(cols), rows_(rows), tile_w_(tile_w), tile_h_(tile_h), origin_col_(origin_col),
      origin_row_(origin_row), solid_(std::move(solid)) {
    if (cols < 0 || rows < 0 || tile_w <= 0 || tile_h <= 0)
        throw std::invalid_argument("tile grid: sizes must be positive");
    if (solid_.size() != static_cast<size_t>(cols) * static_cast<size_t>(rows))
        throw std::invalid_argument("tile grid: solid mask is not cols*rows long");
}

CellRange TileGrid::clip(CellRange r, int64_t origin, int count) {
    return {std::max(r.first, origin), std::min(r.last, origin + count - 1)};
}

}  // namespace ds
