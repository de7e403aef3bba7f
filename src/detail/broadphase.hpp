// SPDX-License-Identifier: MIT
// The entity push-apart pass for many bodies: the same sequential pass over
// the pairs (i, j), i < j, in list order as the all-pairs loop — same pairs,
// same order, each seeing what earlier pairs did — but finding each body's
// partners through a hashed grid of the current boxes instead of trying every
// later body.
#pragma once
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "body.hpp"
#include "extent.hpp"
#include "cell_hash.hpp"

namespace ds {

class TileGrid;

class PairSweep {
public:
    // Runs the pass over bodies[members[0]], bodies[members[1]], … (the
    // solid, non-ghost bodies in list order).
    // `resting`: empty, or per body whether it rested (see resolve_pair).
    // `log`, when given, receives each pair resolved (contacts.hpp's PairLog),
    // and `sides` (if given too) the side of its first body (note_pushed).
    // `rooms`, when given (by body), takes both bodies' boxes after each
    // pair they meet in (note_rooms).
    void run(std::span<Body> bodies, std::span<const size_t> members,
             std::span<const uint8_t> resting = {},
             std::vector<std::pair<uint32_t, uint32_t>>* log = nullptr,
             std::vector<uint8_t>* sides = nullptr, const TileGrid* walls = nullptr,
             Extent* rooms = nullptr);

private:
    CellBox cells(const Body& b) const;
    bool is_big(const CellBox& r) const;
    size_t bucket(int64_t cx, int64_t cy) const;
    void insert(uint32_t m, const CellBox& r);
    void remove(uint32_t m, const CellBox& r);
    // Queues the members after `after` that share a bucket with box r (or
    // are big) and are not queued yet for the current body.
    void query(const CellBox& r, uint32_t after, std::span<const size_t> members, bool all);

    // Fills the grid, choosing the bucket layout from where the members are.
    void file_members(std::span<const Body> bodies, std::span<const size_t> members);

    double inv_cell_ = 1;  // 1 / cell size
    CellLayout layout_;    // dense over the members' starting hull
    std::vector<std::vector<uint32_t>> buckets_;
    std::vector<uint32_t> big_;        // members spanning too many cells: everyone's candidates
    std::vector<uint8_t> is_big_;      // by member
    std::vector<CellBox> box_;         // by member: where it is registered
    std::vector<uint32_t> queued_;     // by member: the body (+1) it was last queued for
    // Candidates of the current body; sorted from `next` on, taken in order.
    std::vector<uint32_t> queue_;
    std::vector<double> sizes_;
    uint32_t current_ = 0;
};

}  // namespace ds
