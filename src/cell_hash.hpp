// The pieces the hashed grids (push-apart, ground support) share: which cell
// a coordinate falls in, and which bucket a cell goes to.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ds {

// ⌊v / cell⌋ given 1/cell. Monotone in v (a product with a positive constant
// rounds monotonely), so overlapping intervals always share a cell; huge
// coordinates are clamped (they only make extra candidates).
inline int64_t cell_index(double v, double inv_cell) {
    constexpr double kLimit = 4.0e18;
    return static_cast<int64_t>(std::clamp(std::floor(v * inv_cell), -kLimit, kLimit));
}

// A bucket for cell (cx, cy) among mask + 1 (a power of two). Distinct cells
// may share a bucket: that only adds candidates.
inline size_t cell_bucket(int64_t cx, int64_t cy, size_t mask) {
    const uint64_t h = static_cast<uint64_t>(cx) * 0x9E3779B97F4A7C15ull ^
                       static_cast<uint64_t>(cy) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>((h ^ (h >> 29)) & mask);
}

}  // namespace ds
