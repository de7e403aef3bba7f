// SPDX-License-Identifier: MIT
// Spatial queries for game logic (semantics §8): boxes overlapping a
// rectangle or holding a point, the overlapping pairs between two sets of
// boxes, and segments cast against boxes and solid cells. Boxes are the
// engine's half-open [x, x+w) × [y, y+h); overlap is aabb_overlap's strict
// overlap; results come in list order.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tile_grid.hpp"

namespace ds {

struct Box {
    double x = 0, y = 0, w = 0, h = 0;
};

// Whether (px, py) lies in the half-open box.
inline bool box_contains(const Box& b, double px, double py) {
    return b.x <= px && px < b.x + b.w && b.y <= py && py < b.y + b.h;
}

// Appends to `out` the index of every box that overlaps `r` (strictly), or
// that holds the point, in ascending order (semantics §8).
void query_rect(std::span<const Box> boxes, const Box& r, std::vector<uint32_t>& out);
void query_point(std::span<const Box> boxes, double px, double py, std::vector<uint32_t>& out);

// Where an element of one set is also an element of the other (the same
// entity chosen by both sides of a pair query): a_in_b[i] is the index in b
// of a[i], or -1; b_in_a the same the other way. Empty spans: the sets share
// nothing.
struct SharedMembers {
    std::span<const int32_t> a_in_b;
    std::span<const int32_t> b_in_a;
};

// What overlapping_pairs keeps between calls, so a warm caller does not allocate.
struct PairQueryScratch {
    std::vector<uint32_t> bucket_start, bucket_items, cursor, seen, candidates, oversized;
    std::vector<double> sizes;
};

// Every pair (i, j) with a[i] and b[j] overlapping strictly, by i then j.
// A box never pairs with itself, and a pair of two boxes that are both in
// both sets is reported once, from the earlier of its two a-indices.
void overlapping_pairs(std::span<const Box> a, std::span<const Box> b, SharedMembers shared,
                       PairQueryScratch& scratch, std::vector<std::pair<uint32_t, uint32_t>>& out);

// A segment from (x0, y0) towards (x1, y1), the end itself not included,
// as boxes do not include their far edges.
struct Segment {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct RayHit {
    double t = 0;       // along the segment, 0 at its start, 1 at its end
    double x = 0, y = 0;  // where it enters; on the entry edge exactly
    int nx = 0, ny = 0;   // the face entered: -1, 0 or 1 (both at a corner)
    int64_t body = -1;    // the box's index, or -1 for a cell
    int64_t col = 0, row = 0;  // the cell (map cells), when body is -1
};

// The boxes the segment enters, in ascending box order (sort by t for the
// nearest). A box holding the start point is not entered: a ray cast from
// inside an entity does not hit the entity (semantics §8).
void raycast_boxes(std::span<const Box> boxes, const Segment& s, std::vector<RayHit>& out);
// The solid cells the segment enters, nearest first; with `first_only`, at
// most one. The cell holding the start point is not entered. Walks only the
// cells inside the grid, so a segment of any length costs at most the grid's
// width plus height in cells (semantics §8).
void raycast_cells(const TileGrid& grid, const Segment& s, bool first_only, std::vector<RayHit>& out);

// Orders hits nearest first; at equal distances boxes (in box order) come
// before cells.
void sort_hits(std::vector<RayHit>& hits);

}  // namespace ds
