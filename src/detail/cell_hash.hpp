// SPDX-License-Identifier: MIT
// The pieces the hashed grids (push-apart, ground support) share: which cell
// a coordinate falls in, and which bucket a cell goes to.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "constants.hpp"
#include "../tile_grid.hpp"

namespace ds {

// A box of grid cells [x0, x1] × [y0, y1], both ends included: what a box,
// or a supporter's top edge, covers in one of the hashed grids. (A run of
// cells along one axis of a tile map is tile_grid.hpp's CellRange.)
struct CellBox {
    int64_t x0, y0, x1, y1;
    bool operator==(const CellBox&) const = default;
};

// ⌊v / cell⌋ given 1/cell. Monotone in v (a product with a positive constant
// rounds monotonely), so overlapping intervals always share a cell; huge
// coordinates are clamped (they only make extra candidates).
inline int64_t cell_index(double v, double inv_cell) { return cell_math::floor_cell(v * inv_cell); }

// 1 / cell size for a grid of n boxes: cells twice the median box size
// (at least 1), so most boxes touch 1-4 cells. The median comes from at
// most 1025 evenly spaced k: any cell size gives the same answers, only
// faster or slower, so a sample does as well as all n and spares a
// selection over 100000 sizes every frame. n must be positive.
template <class Size>
double inverse_cell_size(size_t n, std::vector<double>& scratch, Size&& size) {
    const size_t stride = std::max<size_t>(1, n / kCellSizeSamples);
    scratch.clear();
    for (size_t k = 0; k < n; k += stride) scratch.push_back(size(k));
    const auto mid = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
    std::nth_element(scratch.begin(), mid, scratch.end());
    return 1 / std::max(2 * *mid, 1.0);
}

// A bucket for cell (cx, cy) among mask + 1 (a power of two). Distinct cells
// may share a bucket: that only adds candidates.
inline size_t cell_bucket(int64_t cx, int64_t cy, size_t mask) {
    const uint64_t h = static_cast<uint64_t>(cx) * 0x9E3779B97F4A7C15ull ^
                       static_cast<uint64_t>(cy) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>((h ^ (h >> 29)) & mask);
}

// How a grid maps cells to buckets. Cells inside a hull (where the bodies
// were when the grid was built) map row by row onto the first buckets, so
// neighbouring cells are neighbours in memory; cells outside it are hashed
// over all buckets. Any fixed map is correct: a shared bucket only adds
// candidates.
struct CellLayout {
    int64_t x0 = 0, y0 = 0, w = 0, h = 0;  // the dense hull; w = 0: hash everything
    size_t mask = 0;                        // buckets - 1

    // Lays out for the cell hull [x0, x1] × [y0, y1] (empty when x0 > x1)
    // of n items: densely when the hull has at most 4n cells. Returns the
    // number of buckets, a power of two of at least 2n.
    size_t plan(int64_t hx0, int64_t hy0, int64_t hx1, int64_t hy1, size_t n) {
        size_t buckets = std::bit_ceil(std::max<size_t>(2 * n, 2));
        w = h = 0;
        if (hx0 <= hx1 && hy0 <= hy1) {
            const double cells = (static_cast<double>(hx1) - static_cast<double>(hx0) + 1) *
                                 (static_cast<double>(hy1) - static_cast<double>(hy0) + 1);
            if (cells <= 4.0 * static_cast<double>(n)) {
                x0 = hx0, y0 = hy0, w = hx1 - hx0 + 1, h = hy1 - hy0 + 1;
                buckets = std::max(buckets, std::bit_ceil(static_cast<size_t>(w * h)));
            }
        }
        mask = buckets - 1;
        return buckets;
    }

    size_t bucket(int64_t cx, int64_t cy) const {
        const uint64_t dx = static_cast<uint64_t>(cx - x0), dy = static_cast<uint64_t>(cy - y0);
        if (dx < static_cast<uint64_t>(w) && dy < static_cast<uint64_t>(h))
            return static_cast<size_t>(dy * static_cast<uint64_t>(w) + dx);
        return cell_bucket(cx, cy, mask);
    }
};

}  // namespace ds
