// SPDX-License-Identifier: MIT
#include "ground.hpp"

#include <cmath>

#include "detail/ground_index.hpp"
#include "detail/placed_shape.hpp"

namespace ds {

namespace {

// What holds a body up in the row under its feet (row ⌊(y+h)/th⌋), over
// the columns it spans: a solid cell; a one-way cell (semantics §9) for a
// body not rising, not dropping through, its feet at most kOneWayFooting
// into the cell; and, with `shapes`, a shape (§12) the feet are on or in —
// at or below its surface over the bottom edge and above its underside, a
// one-way shape only within kOneWayFooting of its surface.
bool row_supports(const Body& b, const TileGrid& grid, bool shapes) {
    const double feet = (b.y + b.h).v;
    const int64_t row = cell_of(b.y + b.h, grid.tile_height());
    const CellRange cols = grid.clip_cols(cells_of(b.x, b.w, grid.tile_width()));
    if (grid.clip_rows({row, row}).empty()) return false;  // no cells there: nothing holds it up
    const bool may_stand = b.vy.v >= 0 && !b.drop_through;
    const bool on_top = may_stand && feet - static_cast<double>(row) * grid.tile_height() < kOneWayFooting;
    const shape_math::Span span{b.x.v, (b.x + b.w).v};
    for (int64_t c = cols.first; c <= cols.last; ++c) {
        const uint8_t cell = grid.cell_in(c, row);
        if (cell == kSolidCell || (on_top && cell == kOneWayCell)) return true;
        if (!shapes || cell != kShapedCell) continue;
        const uint16_t id = grid.shape_id_in(c, row);
        const CellShape& sh = grid.shape_at(id);
        if (sh.one_way && !may_stand) continue;
        const shape_math::Placed p(id, c, row, grid);
        double a, z, top, under;
        if (!p.over(span, a, z) || !p.extent(a, z, top, under)) continue;
        if (top <= feet && feet < under && (!sh.one_way || feet - top < kOneWayFooting)) return true;
    }
    return false;
}

}  // namespace

bool tile_supports(const Body& b, const TileGrid& grid) {
    return row_supports(b, grid, grid.has_shapes());
}

// Whole cells only: a body on a shape takes gravity and lands again every
// frame, so one walking down a ramp is snapped and never left resting.
bool rests_on_tile(const Body& b, const TileGrid& grid) {
    const double feet = b.y.v + b.h.v;
    return std::fmod(feet, grid.tile_height()) == 0 && row_supports(b, grid, false);
}

namespace {

// Strict overlap of b's span and o's along x.
bool spans_meet(const Body& b, const Supporter& o) { return b.x.v < o.x + o.w && o.x < b.x.v + b.w.v; }

}  // namespace

// A one-way body (semantics §9) holds up only a body that is not rising
// and not dropping through.
bool may_stand_on(const Body& b, const Supporter& o) {
    return !o.one_way || (b.vy.v >= 0 && !b.drop_through);
}

bool rests_on(const Body& b, const Supporter& o) {
    return o.vy == 0 && o.y == b.y.v + b.h.v && spans_meet(b, o) && may_stand_on(b, o) && o.meets(b);
}

bool entity_supports(const Body& b, const Supporter& o) {
    if (!spans_meet(b, o) || !may_stand_on(b, o) || !o.meets(b)) return false;
    return std::fabs((b.y.v + b.h.v) - o.y) <= kOnSolidTolerance &&
           std::fabs(b.vy.v - o.vy) <= kOnSolidTolerance;
}

bool entity_supports(const Body& b, const Body& o) {
    return o.collides() && entity_supports(b, Supporter::of(o));
}

namespace {

template <class Other>
bool supports_other(const Body& b, const Other& other, std::ptrdiff_t k, std::ptrdiff_t self_slot) {
    return !is_self(b, other, k, self_slot) && entity_supports(b, other);
}

template <class Other>
bool detect_by_scan(Body& b, std::span<const Other> scene, std::ptrdiff_t self_slot,
                    const TileGrid* grid) {
    if (!b.gravity || b.skips(kSkipOnSolid)) return false;
    bool ground = grid && tile_supports(b, *grid);
    for (std::ptrdiff_t k = 0, n = std::ssize(scene); k < n && !ground; ++k)
        ground = supports_other(b, scene[k], k, self_slot);
    b.on_ground = ground;
    return true;
}

template <class Other>
std::ptrdiff_t first_by_scan(const Body& b, std::span<const Other> scene, std::ptrdiff_t self_slot) {
    for (std::ptrdiff_t k = 0, n = std::ssize(scene); k < n; ++k)
        if (supports_other(b, scene[k], k, self_slot)) return k;
    return -1;
}

}  // namespace

std::ptrdiff_t first_supporter(const Body& b, std::span<const Body> scene, std::ptrdiff_t self_slot) {
    return first_by_scan(b, scene, self_slot);
}

std::ptrdiff_t first_supporter(const Body& b, std::span<const Supporter> supporters,
                               std::ptrdiff_t self_slot) {
    return first_by_scan(b, supporters, self_slot);
}

std::ptrdiff_t first_supporter(const Body& b, std::span<const Supporter> supporters,
                               SupportIndex& index, std::ptrdiff_t self_slot) {
    // The index visits candidates in no particular order: take the least.
    std::ptrdiff_t first = -1;
    index.any(b, [&](uint32_t k) {
        const auto slot = static_cast<std::ptrdiff_t>(k);
        if ((first < 0 || slot < first) && supports_other(b, supporters[k], slot, self_slot)) first = slot;
        return false;
    });
    return first;
}

bool detect_on_solid(Body& b, std::span<const Body> scene, std::ptrdiff_t self_slot,
                     const TileGrid* grid) {
    return detect_by_scan(b, scene, self_slot, grid);
}

bool detect_on_supporters(Body& b, std::span<const Supporter> supporters, std::ptrdiff_t self_slot,
                          const TileGrid* grid) {
    return detect_by_scan(b, supporters, self_slot, grid);
}

bool detect_on_supporters(Body& b, std::span<const Supporter> supporters, SupportIndex& index,
                          std::ptrdiff_t self_slot, const TileGrid* grid) {
    if (!b.gravity || b.skips(kSkipOnSolid)) return false;
    b.on_ground = (grid && tile_supports(b, *grid)) ||
                  index.any(b, [&](uint32_t k) { return supports_other(b, supporters[k], k, self_slot); });
    return true;
}

}  // namespace ds
