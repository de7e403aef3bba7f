// SPDX-License-Identifier: MIT
// The sizes every map keeps, loaded or made in memory: one check of tile
// sizes, map sizes and cell extents for both paths, and the cell budget a
// load draws each layer from. Messages name the value and the limit; the
// caller adds where it came from.
#pragma once
#include <cstdint>
#include <string>

#include "../constants.hpp"
#include "../export.hpp"

namespace ds {

// What one load or make may use; the defaults are constants.hpp's.
struct MapLimits {
    int64_t max_cells = kMaxMapCells;  // tile-layer cells across the map
    int64_t max_bytes = kMaxMapBytes;  // the .tmx and its .tsx files together
};

// Whether w × h exceeds `max` (w, h ≥ 0), without overflowing.
DOWNSTROKE_API bool exceeds(int64_t w, int64_t h, int64_t max);

// Each of these returns why the sizes cannot be, or "" when they can.
// Tile sizes: positive and at most kMaxTileSize.
DOWNSTROKE_API std::string tile_size_problem(int64_t tile_w, int64_t tile_h);
// Cells first … first+count−1 of `tile` px: every edge within ±2^53 px, the
// range where the core's coordinates are exact.
DOWNSTROKE_API std::string extent_problem(int64_t first, int64_t count, int64_t tile, const char* axis);
// A finite map (or make-tilemap's): positive size, at most max_cells, tile
// sizes as above, extents as above.
DOWNSTROKE_API std::string map_size_problem(int64_t cols, int64_t rows, int64_t tile_w, int64_t tile_h,
                             int64_t max_cells);

// The cells left for a map's tile layers.
class DOWNSTROKE_API CellBudget {
public:
    explicit CellBudget(int64_t max) : max_(max), left_(max) {}
    int64_t max() const { return max_; }
    int64_t used() const { return max_ - left_; }
    // Takes `cells` (≥ 0) when that many are left; false, taking none, when not.
    bool take(int64_t cells);

private:
    int64_t max_, left_;
};

}  // namespace ds
