#include "tiles.hpp"

#include <algorithm>
#include <cmath>

#include "steps.hpp"

namespace ds {

namespace {

// One axis of a body, so x and y share a single resolution routine.
struct Axis {
    Num& pos;
    Num& vel;
    Num move;  // this (sub-)frame's displacement: vel, or vel·h
    Num size;
    int tile;
};

// The cells to test along the moving axis. Discrete: the box as it is now.
// Swept: the box plus every cell its leading edge crossed this frame, which
// equals the box whenever |v| ≤ size.
CellRange candidates(const Axis& a, CollisionMode mode) {
    if (mode == CollisionMode::Discrete || !(a.size.v > 0)) return cells_of(a.pos, a.size, a.tile);
    const Num start = a.pos - a.move;  // where the box began the move
    if (a.vel.v > 0) {
        const Num lead_start = start + a.size;  // the right (bottom) edge before the move
        const Num lo = lead_start.v < a.pos.v ? lead_start : a.pos;
        return cells_of(lo, (a.pos + a.size) - lo, a.tile);
    }
    const Num hi = start.v > a.pos.v + a.size.v ? start : a.pos + a.size;
    return cells_of(a.pos, hi - a.pos, a.tile);
}

// Walks candidate cells from the side the body moves from, so the first
// solid cell met is the one it reaches first.
template <typename Solid>
void resolve_axis(Axis a, CellRange along, CellRange across, Solid solid) {
    if (along.empty() || across.empty()) return;
    const bool forward = a.vel.v > 0;
    for (int64_t i = 0, n = along.last - along.first + 1; i < n; ++i) {
        const int64_t c = forward ? along.first + i : along.last - i;
        for (int64_t k = across.first; k <= across.last; ++k) {
            if (!solid(c, k)) continue;
            const bool exact = a.pos.exact && a.size.exact;
            const double edge = static_cast<double>(forward ? c : c + 1) * a.tile;
            a.pos = forward ? Num{edge - a.size.v, exact} : Num{edge, exact};
            a.vel = Num::integer(0);
            return;
        }
    }
}

}  // namespace

bool resolve_tile_collisions_x(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s) {
    if (!grid || b.vx.v == 0 || b.skips(kSkipTileX)) return false;
    Axis a{b.x, b.vx, s.share(b.vx), b.w, grid->tile_width()};
    const CellRange cols = grid->clip_cols(candidates(a, mode));
    const CellRange rows = grid->clip_rows(cells_of(b.y, b.h, grid->tile_height()));
    resolve_axis(a, cols, rows,
                 [&](int64_t c, int64_t r) { return grid->solid(c, r); });
    return true;
}

bool resolve_tile_collisions_y(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s) {
    if (!grid || b.vy.v == 0 || b.skips(kSkipTileY)) return false;
    Axis a{b.y, b.vy, s.share(b.vy), b.h, grid->tile_height()};
    const CellRange rows = grid->clip_rows(candidates(a, mode));
    const CellRange cols = grid->clip_cols(cells_of(b.x, b.w, grid->tile_width()));
    resolve_axis(a, rows, cols,
                 [&](int64_t r, int64_t c) { return grid->solid(c, r); });
    return true;
}

bool tile_supports(const Body& b, const TileGrid& grid) {
    const int64_t row = cell_of(b.y + b.h, grid.tile_height());
    const CellRange cols = grid.clip_cols(cells_of(b.x, b.w, grid.tile_width()));
    for (int64_t c = cols.first; c <= cols.last; ++c)
        if (grid.solid(c, row)) return true;
    return false;
}

bool rests_on_tile(const Body& b, const TileGrid& grid) {
    const double feet = b.y.v + b.h.v;
    return std::fmod(feet, grid.tile_height()) == 0 && tile_supports(b, grid);
}

namespace {

// Strict overlap of b's span and o's along x.
bool spans_meet(const Body& b, const Supporter& o) { return b.x.v < o.x + o.w && o.x < b.x.v + b.w.v; }

}  // namespace

bool rests_on(const Body& b, const Supporter& o) {
    return o.vy == 0 && o.y == b.y.v + b.h.v && spans_meet(b, o);
}

bool entity_supports(const Body& b, const Supporter& o) {
    if (!spans_meet(b, o)) return false;
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

}  // namespace

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
