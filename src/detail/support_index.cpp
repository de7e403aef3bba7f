// SPDX-License-Identifier: MIT
#include "support_index.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>

#include "constants.hpp"
#include "cell_hash.hpp"
#include "steps.hpp"

namespace ds {

CellBox SupportIndex::top_cells(const Supporter& o) const {
    const double xa = o.x, xb = o.x + o.w;
    const int64_t row = cell_index(o.y, inv_ch_);
    return {cell_index(std::min(xa, xb), inv_cw_), row, cell_index(std::max(xa, xb), inv_cw_), row};
}

CellBox SupportIndex::query_cells(const Body& b) const {
    // Supporters' tops within the tolerance of the feet. A top qualifies when
    // the rounded |feet − top| ≤ tolerance, so the exact one exceeds it by at
    // most half an ulp of the tolerance (2⁻⁵¹); the slack covers that and the
    // rounding of feet ± (tolerance + slack) itself, and cell_index is
    // monotone, so every qualifying top's row is among those queried.
    const double xa = b.x.v, xb = b.x.v + b.w.v, feet = b.y.v + b.h.v;
    const double reach = kOnSolidTolerance + 1e-9 + 1e-12 * std::fabs(feet);
    return {cell_index(std::min(xa, xb), inv_cw_), cell_index(feet - reach, inv_ch_),
            cell_index(std::max(xa, xb), inv_cw_), cell_index(feet + reach, inv_ch_)};
}

size_t SupportIndex::bucket(int64_t cx, int64_t cy) const {
    return layout_.bucket(cx, cy);
}

void SupportIndex::build(std::span<const Supporter> bodies) {
    const auto n = static_cast<uint32_t>(bodies.size());
    if (n > 0) inv_cw_ = inverse_cell_size(n, widths_, [&](size_t k) { return std::fabs(bodies[k].w); });
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    tops_.clear();
    for (const Supporter& o : bodies) {
        const CellBox r = tops_.emplace_back(top_cells(o));
        if (r.x1 - r.x0 >= kMaxFiledSpan) continue;
        x0 = std::min(x0, r.x0), y0 = std::min(y0, r.y0);
        x1 = std::max(x1, r.x1), y1 = std::max(y1, r.y1);
    }
    const size_t buckets = layout_.plan(x0, y0, x1, y1, n);
    start_.assign(buckets + 1, 0);
    big_.clear();
    seen_.assign(n, 0);
    stamp_ = 0;
    // Counting sort by bucket: count, prefix-sum, place.
    auto each_cell = [&](const CellBox& r, auto&& f) {
        for (int64_t cx = r.x0; cx <= r.x1; ++cx) f(bucket(cx, r.y0));
    };
    for (uint32_t k = 0; k < n; ++k) {
        const CellBox& r = tops_[k];
        if (r.x1 - r.x0 >= kMaxFiledSpan) big_.push_back(k);
        else each_cell(r, [&](size_t h) { ++start_[h + 1]; });
    }
    for (size_t h = 0; h < buckets; ++h) start_[h + 1] += start_[h];
    items_.resize(start_[buckets]);
    cursor_.assign(start_.begin(), start_.end() - 1);
    for (uint32_t k = 0; k < n; ++k) {
        const CellBox& r = tops_[k];
        if (r.x1 - r.x0 >= kMaxFiledSpan) continue;
        each_cell(r, [&](size_t h) { items_[cursor_[h]++] = k; });
    }
}

}  // namespace ds
