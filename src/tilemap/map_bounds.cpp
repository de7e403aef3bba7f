// SPDX-License-Identifier: MIT
#include "map_bounds.hpp"

#include "../number.hpp"

namespace ds {

namespace {

std::string size_text(int64_t w, int64_t h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

bool exceeds(int64_t w, int64_t h, int64_t max) { return w > 0 && h > max / w; }

std::string tile_size_problem(int64_t tile_w, int64_t tile_h) {
    if (tile_w <= 0 || tile_h <= 0) return "tile size " + size_text(tile_w, tile_h) + " is not positive";
    if (tile_w > kMaxTileSize || tile_h > kMaxTileSize)
        return "tile size " + size_text(tile_w, tile_h) + " is larger than the limit of " +
               std::to_string(kMaxTileSize) + " px";
    return "";
}

std::string extent_problem(int64_t first, int64_t count, int64_t tile, const char* axis) {
    // Callers keep |first| and count within 2^32 and tile within 2^24: no overflow.
    const auto limit = static_cast<int64_t>(kMaxExact);
    const int64_t lo = first * tile, hi = (first + count) * tile;
    if (lo >= -limit && hi <= limit) return "";
    return std::string(axis) + " cells " + std::to_string(first) + " to " +
           std::to_string(first + count - 1) + " of " + std::to_string(tile) +
           " px reach beyond 2^53 px, where coordinates stop being exact";
}

std::string map_size_problem(int64_t cols, int64_t rows, int64_t tile_w, int64_t tile_h,
                             int64_t max_cells) {
    if (cols <= 0 || rows <= 0) return "map size " + size_text(cols, rows) + " is not positive";
    if (exceeds(cols, rows, max_cells))
        return "map size " + size_text(cols, rows) + " is more than the max-cells limit of " +
               std::to_string(max_cells) + " cells";
    if (std::string p = tile_size_problem(tile_w, tile_h); !p.empty()) return p;
    if (std::string p = extent_problem(0, cols, tile_w, "column"); !p.empty()) return p;
    return extent_problem(0, rows, tile_h, "row");
}

bool CellBudget::take(int64_t cells) {
    if (cells > left_) return false;
    left_ -= cells;
    return true;
}

}  // namespace ds
