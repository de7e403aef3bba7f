// SPDX-License-Identifier: MIT
#include "carry.hpp"

#include <algorithm>

#include <cmath>

#include "constants.hpp"
#include "contacts.hpp"
#include "detail/body_axis.hpp"
#include "tiles.hpp"

namespace ds {

namespace {

struct Displacement {
    Num dx, dy;
    bool moved() const { return dx.v != 0 || dy.v != 0; }
};

Displacement displacement(const Body& now, const Body& then) { return {now.x - then.x, now.y - then.y}; }

// b moved by d along one axis as that axis's tile step would move it with
// velocity d (its own velocity untouched); returns whether a solid cell
// stopped it.
using AxisOf = BodyAxis (*)(Body&);
using TileStep = bool (*)(Body&, const TileGrid*, CollisionMode, SubStep);

bool carry_along(Body& b, Num d, AxisOf axis, TileStep resolve, const TileGrid* grid, CollisionMode mode) {
    if (d.v == 0) return false;
    Body moved = b;
    moved.bounce = {};  // a stop is read from the velocity it zeroes
    BodyAxis m = axis(moved);
    m.pos = axis(b).pos + d;
    m.vel = d;
    SubStep carried;
    carried.carried = true;
    resolve(moved, grid, mode, carried);
    // Both coordinates: a rider carried along x onto a ramp climbs it (§12).
    b.x = moved.x;
    b.y = moved.y;
    return m.vel.v == 0;
}

void carry_one(Body& b, Displacement d, const TileGrid* grid, CollisionMode mode) {
    carry_along(b, d.dx, along_x, resolve_tile_collisions_x, grid, mode);
    if (carry_along(b, d.dy, along_y, resolve_tile_collisions_y, grid, mode) && d.dy.v < 0) b.crushed = true;
}

// r stood on the carrier c: overlapping it horizontally, its feet within
// the tolerance of c's top; on a one-way c, not rising nor dropping
// through. Not their speeds, as ground detection compares: push-apart
// zeroes a rider's vy every frame, whatever the carrier's.
bool rides(const Body& r, const Body& c) {
    return r.x.v < c.x.v + c.w.v && c.x.v < r.x.v + r.w.v &&
           categories_meet(r, c) && std::fabs((r.y.v + r.h.v) - c.y.v) <= kOnSolidTolerance &&
           (!c.one_way || (r.vy.v >= 0 && !r.drop_through));
}

}  // namespace

void clear_crushed(std::span<Body> bodies, std::span<const size_t> members) {
    for (const size_t i : members)
        if (is_crushable(bodies[i])) bodies[i].crushed = false;
}

void carry_riders(std::span<Body> bodies, std::span<const Body> start,
                  std::span<const size_t> carriers, std::span<const size_t> members,
                  const TileGrid* grid, CollisionMode mode, CarryScratch& scratch) {
    scratch.ridden.assign(bodies.size(), 0);
    for (const size_t c : carriers) {
        const Displacement d = displacement(bodies[c], start[c]);
        if (!d.moved()) continue;
        // Who stood on it is read from the (sub-)frame start, so the carry
        // does not depend on the order of the per-entity steps.
        for (const size_t r : members) {
            if (scratch.ridden[r] || !may_ride(bodies[r]) || !rides(start[r], start[c])) continue;
            scratch.ridden[r] = 1;
            carry_one(bodies[r], d, grid, mode);
        }
    }
}

void note_in_way(std::span<const Body> bodies, std::span<const Body> start,
                 std::span<const size_t> carriers, std::span<const size_t> members,
                 CarryScratch& scratch) {
    scratch.in_way.clear();
    for (const size_t m : members) {
        if (!is_crushable(bodies[m])) continue;
        for (const size_t c : carriers)
            if (!bodies[c].one_way && categories_meet(bodies[m], bodies[c]) &&
                displacement(bodies[c], start[c]).moved() &&
                aabb_overlap(bodies[m], bodies[c])) {
                scratch.in_way.push_back(m);
                break;
            }
    }
}

void crush_in_way(std::span<Body> bodies, std::span<const size_t> carriers, const TileGrid* grid,
                  bool walls_cut, const CarryScratch& scratch) {
    if (grid == nullptr) return;
    auto held = [&](const Body& m) {
        return walls_cut && std::any_of(carriers.begin(), carriers.end(), [&](size_t c) {
                   return !bodies[c].one_way && categories_meet(m, bodies[c]) && aabb_overlap(m, bodies[c]);
               });
    };
    for (const size_t m : scratch.in_way)
        if (overlaps_solid(bodies[m], *grid) || held(bodies[m])) bodies[m].crushed = true;
}

}  // namespace ds
