// SPDX-License-Identifier: MIT
// Which frame-start bodies could hold a body up: a hashed grid over the
// supporters' top edges, so ground detection looks at the few bodies near a
// body's feet instead of the whole scene. The answer is the same as the
// linear scan's (ground detection only asks whether any supporter qualifies).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "constants.hpp"
#include "body.hpp"
#include "cell_hash.hpp"
#include "supporter.hpp"

namespace ds {

class SupportIndex {
public:
    // Indexes the frame's supporters.
    void build(std::span<const Supporter> supporters);

    // Calls accept(k) for every indexed body k whose top edge lies near b's
    // feet and whose span meets b's (each at most once); true as soon as one
    // call returns true.
    template <class Accept>
    bool any(const Body& b, Accept&& accept) {
        ++stamp_;
        for (uint32_t k : big_)
            if (visit(k) && accept(k)) return true;
        const CellBox r = query_cells(b);
        if (r.x1 - r.x0 > kMaxQuerySpan) {  // a very wide body: everyone is near
            for (uint32_t k = 0; k < seen_.size(); ++k)
                if (visit(k) && accept(k)) return true;
            return false;
        }
        for (int64_t cy = r.y0; cy <= r.y1; ++cy)
            for (int64_t cx = r.x0; cx <= r.x1; ++cx) {
                const size_t h = bucket(cx, cy);
                for (uint32_t i = start_[h]; i < start_[h + 1]; ++i)
                    if (visit(items_[i]) && accept(items_[i])) return true;
            }
        return false;
    }

private:
    CellBox top_cells(const Supporter& o) const;
    CellBox query_cells(const Body& b) const;
    size_t bucket(int64_t cx, int64_t cy) const;
    bool visit(uint32_t k) {
        if (seen_[k] == stamp_) return false;
        seen_[k] = stamp_;
        return true;
    }

    double inv_cw_ = 1, inv_ch_ = 1.0 / 16;  // 1 / cell width and height
    std::vector<uint32_t> start_;  // bucket h holds items_[start_[h] .. start_[h+1])
    std::vector<uint32_t> items_;
    std::vector<uint32_t> cursor_;  // build scratch
    std::vector<CellBox> tops_;     // build scratch: each supporter's top cells
    std::vector<uint32_t> big_;    // spanning many columns: always candidates
    std::vector<uint32_t> seen_;
    std::vector<double> widths_;
    uint32_t stamp_ = 0;
    CellLayout layout_;  // dense over the supporters' top edges
};

}  // namespace ds
