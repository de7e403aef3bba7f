#include "tiles.hpp"

#include <algorithm>
#include <cmath>

#include "detail/body_axis.hpp"
#include "steps.hpp"

namespace ds {

namespace {

// One axis of a body as a tile step sees it, so x and y share a single
// resolution routine: the body's axis plus this step's move and cell size.
struct TileAxis {
    BodyAxis body;
    Num move;  // this (sub-)frame's displacement: vel, or vel·h
    int tile;
};

// The cells to test along the moving axis. Discrete: the box as it is now.
// Swept: the box plus every cell its leading edge crossed this frame, which
// equals the box whenever |v| ≤ size.
CellRange candidates(const TileAxis& t, CollisionMode mode) {
    const BodyAxis& a = t.body;
    if (mode == CollisionMode::Discrete || !(a.size.v > 0)) return cells_of(a.pos, a.size, t.tile);
    const Num start = a.pos - t.move;  // where the box began the move
    if (a.vel.v > 0) {
        const Num lead_start = start + a.size;  // the right (bottom) edge before the move
        const Num lo = lead_start.v < a.pos.v ? lead_start : a.pos;
        return cells_of(lo, (a.pos + a.size) - lo, t.tile);
    }
    const Num hi = start.v > a.pos.v + a.size.v ? start : a.pos + a.size;
    return cells_of(a.pos, hi - a.pos, t.tile);
}

// Walks candidate cells from the side the body moves from, so the first
// solid cell met is the one it reaches first. Returns whether one stopped it.
template <typename Solid>
bool resolve_axis(const TileAxis& t, CellRange along, CellRange across, Solid solid) {
    const BodyAxis& a = t.body;
    if (along.empty() || across.empty()) return false;
    const bool forward = a.vel.v > 0;
    for (int64_t i = 0, n = along.last - along.first + 1; i < n; ++i) {
        const int64_t c = forward ? along.first + i : along.last - i;
        for (int64_t k = across.first; k <= across.last; ++k) {
            if (!solid(c, k)) continue;
            const bool exact = a.pos.exact && a.size.exact;
            const double edge = static_cast<double>(forward ? c : c + 1) * t.tile;
            a.pos = forward ? Num{edge - a.size.v, exact} : Num{edge, exact};
            a.vel = Num::integer(0);
            return true;
        }
    }
    return false;
}

// A contact body's #:blocked (semantics §10): the step owns its axis's
// sides, set from this call alone, or, in a later sub-frame, added.
void note_blocked(Body& b, uint8_t axis, uint8_t sides, SubStep s) {
    if (!b.contacts) return;
    const uint8_t kept = s.gather ? b.blocked : static_cast<uint8_t>(b.blocked & ~axis);
    b.blocked = static_cast<uint8_t>((kept & kSidesAll) | sides);
}

uint8_t side(bool stopped, Num vel, uint8_t forward, uint8_t backward) {
    return stopped ? (vel.v > 0 ? forward : backward) : 0;
}

}  // namespace

bool resolve_tile_collisions_x(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s) {
    if (b.skips(kSkipTileX)) return false;
    if (!grid || b.vx.v == 0) {
        note_blocked(b, kSidesX, 0, s);
        return false;
    }
    const Num vx = b.vx;
    const TileAxis a{along_x(b), s.share(b.vx), grid->tile_width()};
    const CellRange cols = grid->clip_cols(candidates(a, mode));
    const CellRange rows = grid->clip_rows(cells_of(b.y, b.h, grid->tile_height()));
    const bool stopped = resolve_axis(a, cols, rows,
                                      [&](int64_t c, int64_t r) { return grid->solid(c, r); });
    note_blocked(b, kSidesX, side(stopped, vx, kSideRight, kSideLeft), s);
    return true;
}

bool resolve_tile_collisions_y(Body& b, const TileGrid* grid, CollisionMode mode, SubStep s) {
    if (b.skips(kSkipTileY)) return false;
    if (!grid || b.vy.v == 0) {
        note_blocked(b, kSidesY, 0, s);
        return false;
    }
    const Num vy = b.vy;
    const TileAxis a{along_y(b), s.share(b.vy), grid->tile_height()};
    const CellRange rows = grid->clip_rows(candidates(a, mode));
    const CellRange cols = grid->clip_cols(cells_of(b.x, b.w, grid->tile_width()));
    // A one-way cell stops a body falling onto it whose feet were at or above
    // its top when this move began (semantics §9); never one rising or
    // dropping through.
    const bool may_land = b.vy.v > 0 && !b.drop_through;
    const double feet_before = (b.y - a.move + b.h).v;
    const double th = grid->tile_height();
    const bool stopped = resolve_axis(a, rows, cols, [&](int64_t r, int64_t c) {
        const uint8_t cell = grid->cell(c, r);
        return cell == kSolidCell ||
               (may_land && cell == kOneWayCell && feet_before <= static_cast<double>(r) * th);
    });
    note_blocked(b, kSidesY, side(stopped, vy, kSideDown, kSideUp), s);
    return true;
}

}  // namespace ds
