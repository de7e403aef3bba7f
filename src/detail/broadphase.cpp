// SPDX-License-Identifier: MIT
#include "broadphase.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>

#include "constants.hpp"
#include "contacts.hpp"

namespace ds {

CellBox PairSweep::cells(const Body& b) const {
    // The closed hull of each interval: for any widths (zero or negative too),
    // two boxes that overlap by the strict formula have intersecting hulls.
    const double xa = b.x.v, xb = b.x.v + b.w.v, ya = b.y.v, yb = b.y.v + b.h.v;
    return {cell_index(std::min(xa, xb), inv_cell_), cell_index(std::min(ya, yb), inv_cell_),
            cell_index(std::max(xa, xb), inv_cell_), cell_index(std::max(ya, yb), inv_cell_)};
}

bool PairSweep::is_big(const CellBox& r) const {
    return r.x1 - r.x0 >= kMaxFiledSpan || r.y1 - r.y0 >= kMaxFiledSpan;
}

size_t PairSweep::bucket(int64_t cx, int64_t cy) const { return layout_.bucket(cx, cy); }

void PairSweep::file_members(std::span<const Body> bodies, std::span<const size_t> members) {
    const auto n = static_cast<uint32_t>(members.size());
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    for (uint32_t m = 0; m < n; ++m) {
        const CellBox r = cells(bodies[members[m]]);
        box_[m] = r;
        is_big_[m] = is_big(r);
        if (is_big_[m]) continue;
        x0 = std::min(x0, r.x0), y0 = std::min(y0, r.y0);
        x1 = std::max(x1, r.x1), y1 = std::max(y1, r.y1);
    }
    const size_t want = layout_.plan(x0, y0, x1, y1, n);
    if (buckets_.size() != want) buckets_.resize(want);
    for (auto& b : buckets_) b.clear();
    big_.clear();
    for (uint32_t m = 0; m < n; ++m) {
        if (is_big_[m]) big_.push_back(m);
        else insert(m, box_[m]);
    }
}

void PairSweep::insert(uint32_t m, const CellBox& r) {
    box_[m] = r;
    for (int64_t cy = r.y0; cy <= r.y1; ++cy)
        for (int64_t cx = r.x0; cx <= r.x1; ++cx) buckets_[bucket(cx, cy)].push_back(m);
}

void PairSweep::remove(uint32_t m, const CellBox& r) {
    for (int64_t cy = r.y0; cy <= r.y1; ++cy)
        for (int64_t cx = r.x0; cx <= r.x1; ++cx) {
            auto& b = buckets_[bucket(cx, cy)];
            auto it = std::find(b.begin(), b.end(), m);
            if (it != b.end()) {
                *it = b.back();
                b.pop_back();
            }
        }
}

void PairSweep::query(const CellBox& r, uint32_t after, std::span<const size_t> members, bool all) {
    auto push = [&](uint32_t m) {
        if (m <= after || queued_[m] == current_ + 1) return;
        queued_[m] = current_ + 1;
        queue_.push_back(m);
    };
    if (all) {
        for (uint32_t m = after + 1; m < members.size(); ++m) push(m);
        return;
    }
    for (int64_t cy = r.y0; cy <= r.y1; ++cy)
        for (int64_t cx = r.x0; cx <= r.x1; ++cx)
            for (uint32_t m : buckets_[bucket(cx, cy)]) push(m);
    for (uint32_t m : big_) push(m);
}

void PairSweep::run(std::span<Body> bodies, std::span<const size_t> members,
                    std::span<const uint8_t> resting, PairLog* log, SideLog* sides,
                    const TileGrid* walls, Extent* rooms) {
    auto rests = [&](uint32_t m) { return !resting.empty() && resting[members[m]] != 0; };
    const auto n = static_cast<uint32_t>(members.size());
    inv_cell_ = inverse_cell_size(n, sizes_, [&](size_t m) {
        const Body& b = bodies[members[m]];
        return std::max(std::fabs(b.w.v), std::fabs(b.h.v));
    });

    is_big_.assign(n, 0);
    box_.resize(n);
    queued_.assign(n, 0);
    file_members(bodies, members);
    for (uint32_t a = 0; a < n; ++a) {
        current_ = a;
        // Earlier bodies stay in the grid: query() passes over them.
        Body& first = bodies[members[a]];
        queue_.clear();
        size_t next = 0;
        // Where a is filed is where it is: it moved since only as someone's
        // second, and was re-filed then. (Big bodies are filed nowhere.)
        CellBox queried = is_big_[a] ? cells(first) : box_[a];
        query(queried, a, members, is_big_[a] != 0);
        std::sort(queue_.begin(), queue_.end());
        while (next < queue_.size()) {
            const uint32_t b = queue_[next++];
            Body& second = bodies[members[b]];
            if (!aabb_overlap(first, second)) continue;
            const double ax = first.x.v, ay = first.y.v, bx = second.x.v, by = second.y.v;
            const uint8_t side = meet(first, second, rests(a), rests(b), walls);
            if (side == 0) continue;
            note_pushed(log, sides, members[a], members[b], side);
            note_rooms(rooms, members[a], first, members[b], second);
            // Re-file b only when it changed cells (sizes never change, so
            // a small body stays small).
            if ((second.x.v != bx || second.y.v != by) && !is_big_[b]) {
                const CellBox moved = cells(second);
                if (moved != box_[b]) {
                    remove(b, box_[b]);
                    insert(b, moved);
                }
            }
            // a moved into other cells: later bodies it may now overlap
            // become partners too — only those after b, as the all-pairs loop
            // has passed the rest. (Within the same cells, they are all
            // queued already.)
            if ((first.x.v != ax || first.y.v != ay) && !is_big_[a]) {
                const CellBox now = cells(first);
                if (now != queried) {
                    const size_t had = queue_.size();
                    query(now, b, members, false);
                    queried = now;
                    // Every candidate still to come lies after b: sorting
                    // them with the new ones keeps the all-pairs order.
                    if (queue_.size() != had)
                        std::sort(queue_.begin() + static_cast<std::ptrdiff_t>(next), queue_.end());
                }
            }
        }
    }
}

}  // namespace ds
