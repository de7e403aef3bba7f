#include "tile_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace ds {

namespace {

// ⌊a/b⌋ and ⌈a/b⌉ for b > 0 in integers: exact for every int64.
int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && (a < 0)); }
int64_t ceil_div(int64_t a, int64_t b) { return a / b + ((a % b != 0) && (a > 0)); }

// Doubles beyond int64 are clamped: such cells lie outside any grid anyway.
int64_t to_cell(double c) {
    constexpr double kLimit = 4.0e18;
    return static_cast<int64_t>(std::clamp(c, -kLimit, kLimit));
}

// Tiles are nearly always a power of two wide: a shift then does the
// division (an arithmetic shift floors negatives too).
bool power_of_two(int tile) { return (tile & (tile - 1)) == 0; }

// Exact and small enough for int64 arithmetic without overflow (exact
// integers can be any size; past 2^61 the double path, which clamps, is
// exact enough: such cells lie outside any map).
bool integral(Num n) { return n.exact && std::fabs(n.v) < 2.3e18; }

}  // namespace

CellRange cells_of(Num pos, Num size, int tile) {
    if (!(size.v > 0)) return {};
    if (integral(pos) && integral(size)) {
        const auto p = static_cast<int64_t>(pos.v), s = static_cast<int64_t>(size.v);
        if (power_of_two(tile)) {
            const int k = std::countr_zero(static_cast<unsigned>(tile));
            return {p >> k, ((p + s + tile - 1) >> k) - 1};
        }
        return {floor_div(p, tile), ceil_div(p + s, tile) - 1};
    }
    return {to_cell(std::floor(pos.v / tile)), to_cell(std::ceil((pos.v + size.v) / tile)) - 1};
}

int64_t cell_of(Num pos, int tile) {
    if (integral(pos)) {
        const auto p = static_cast<int64_t>(pos.v);
        return power_of_two(tile) ? p >> std::countr_zero(static_cast<unsigned>(tile)) : floor_div(p, tile);
    }
    return to_cell(std::floor(pos.v / tile));
}

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
