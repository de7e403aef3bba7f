// SPDX-License-Identifier: MIT
#include "contacts.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bounce.hpp"
#include "detail/body_axis.hpp"
#include "constants.hpp"
#include "detail/contact_scratch.hpp"
#include "detail/tile_clip.hpp"

namespace ds {

namespace {

double overlap(Num p1, Num s1, Num p2, Num s2) {
    return std::min(p1.v + s1.v, p2.v + s2.v) - std::max(p1.v, p2.v);
}

// A movable body against an immovable one. Landing wins while the mover's
// centre is still above the solid's, so a narrow side overlap on a platform
// edge does not shove it sideways; otherwise the shallower axis.
// The velocity a push off a fixed body leaves: 0 (the seed), or with bounce
// (§13) the rebound of a velocity that ran into it (`into`: its sign
// pointed at the fixed body); one moving away keeps 0 too.
Num stopped_by(Num v, bool into, Num bounce) { return into ? rebound(v, bounce) : Num::integer(0); }

// Puts a body's position along one axis at `target`: there under the
// seed's rule (no walls) or when nothing stops the move, else as far as
// clipped_push lets it go (§4, push-apart never leaves a body in a solid).
void place(Body& b, bool x_axis, Num target, const TileGrid* walls) {
    Num& pos = x_axis ? b.x : b.y;
    if (walls) {
        const Num d = target - pos;
        const Num cut = clipped_push(b, x_axis, d, *walls);
        if (cut.v != d.v) {
            pos = pos + cut;
            return;
        }
    }
    pos = target;
}

// Returns the side of m that met s (§10). `bounce` is the pair's, taken in
// list order (§13: on a tie, the earlier entity's), whichever of the two moves.
uint8_t push_off_immovable(Body& m, const Body& s, double ox, double oy, Num bounce,
                           const TileGrid* walls) {
    if (2 * m.y.v + m.h.v < 2 * s.y.v + s.h.v) {
        place(m, false, s.y - m.h, walls);
        m.vy = stopped_by(m.vy, m.vy.v > 0, bounce);
        return kSideDown;
    }
    if (ox < oy) {
        const bool left = 2 * m.x.v + m.w.v < 2 * s.x.v + s.w.v;
        place(m, true, left ? s.x - m.w : s.x + s.w, walls);
        m.vx = stopped_by(m.vx, left ? m.vx.v > 0 : m.vx.v < 0, bounce);
        return left ? kSideRight : kSideLeft;
    }
    place(m, false, s.y + s.h, walls);
    m.vy = stopped_by(m.vy, m.vy.v < 0, bounce);
    return kSideUp;
}

// Two movable bodies' velocities along the axis they were pushed apart on,
// `neg` the one moved the negative way. The seed's −1 and +1; with bounce
// (§13) and the two closing faster than kBounceRestSpeed, a collision of
// equal masses: they keep their mean and part at `bounce` times the speed
// they closed at (bounce 1: they swap velocities, exactly).
void part(Num& neg, Num& pos, Num bounce) {
    const double closing = neg.v - pos.v;
    if (bounce.v == 0 || !(closing > kBounceRestSpeed)) {
        neg = Num::integer(-1);
        pos = Num::integer(1);
    } else if (bounce.exact) {
        std::swap(neg, pos);
    } else {
        const double mean = (neg.v + pos.v) / 2, half = bounce.v * closing / 2;
        neg = Num::flonum(mean - half);
        pos = Num::flonum(mean + half);
    }
}

// Whether `a` is on the negative side of `b` along an axis (twice their
// centres): the one moved the negative way, the earlier (a) on a tie.
bool negative_of(double a_centre2, double b_centre2) { return !(b_centre2 < a_centre2); }

// The side of `a` facing the other body along x or y, `a_negative` as above.
uint8_t facing(bool along_x, bool a_negative) {
    if (along_x) return a_negative ? kSideRight : kSideLeft;
    return a_negative ? kSideDown : kSideUp;
}

// Two movable bodies share the overlap along one axis. `a` is the earlier in
// list order: it moves negative on a tie and takes the larger integer half.
// With walls (§4, push-apart never leaves a body in a solid), a share a
// solid cell cuts short goes to b, cut again at b's cells, and what b could
// not take goes back to a (cut again) when a was not cut itself; the rest is
// dropped. Returns whether a moved the negative way.
bool push_apart(Body& a_body, Body& b_body, bool x_axis, double o, Num bounce, const TileGrid* walls) {
    const BodyAxis a = x_axis ? along_x(a_body) : along_y(a_body);
    const BodyAxis b = x_axis ? along_x(b_body) : along_y(b_body);
    const bool exact = a.pos.exact && a.size.exact && b.pos.exact && b.size.exact;
    const double a_share = exact ? std::ceil(o / 2) : o / 2;
    const double b_share = exact ? o - a_share : o / 2;
    const bool a_negative = negative_of(a.centre2(), b.centre2());
    const Num da{a_negative ? -a_share : a_share, exact}, db{a_negative ? b_share : -b_share, exact};
    if (!walls) {
        a.pos = a.pos + da;
        b.pos = b.pos + db;
    } else {
        const Num ca = clipped_push(a_body, x_axis, da, *walls);
        a.pos = a.pos + ca;
        const Num a_left = da - ca;  // what a could not take, signed as da
        const Num want_b = a_left.v == 0 ? db : db - a_left;
        const Num cb = clipped_push(b_body, x_axis, want_b, *walls);
        b.pos = b.pos + cb;
        const Num b_left = want_b - cb;
        if (a_left.v == 0 && b_left.v != 0) a.pos = a.pos + clipped_push(a_body, x_axis, -b_left, *walls);
    }
    if (a_negative) part(a.vel, b.vel, bounce);
    else part(b.vel, a.vel, bounce);
    return a_negative;
}

// The side of `a` that met `b` when nothing moved them (§10): the axis on
// which their overlap began last, from their relative speed — along x when
// ox/|Δvx| < oy/|Δvy|, compared as ox·|Δvy| < oy·|Δvx| so that an axis
// without relative speed overlapped from the start — and where that does
// not decide (no relative speed, or a tie), the axis of least penetration.
// So a fast fall onto a corner (ox 5, oy 9 at 13 px/frame down, 4 across)
// is met from above, where least penetration alone said from the side. The
// direction is from the centres, a tie as push_apart breaks it.
uint8_t entry_side(const Body& a, const Body& b) {
    const double ox = overlap(a.x, a.w, b.x, b.w), oy = overlap(a.y, a.h, b.y, b.h);
    const double x_later = ox * std::fabs(a.vy.v - b.vy.v), y_later = oy * std::fabs(a.vx.v - b.vx.v);
    const bool along_x = x_later != y_later ? x_later < y_later : ox < oy;
    return along_x ? facing(true, negative_of(2 * a.x.v + a.w.v, 2 * b.x.v + b.w.v))
                   : facing(false, negative_of(2 * a.y.v + a.h.v, 2 * b.y.v + b.h.v));
}

}  // namespace

bool collision_eligible(const Body& a, const Body& b) {
    return a.collides() && b.collides() && categories_meet(a, b) && aabb_overlap(a, b);
}

namespace {

// `upper` comes down on `rester`: its centre is the higher of the two.
bool lands_on(const Body& upper, const Body& rester) {
    return 2 * upper.y.v + upper.h.v < 2 * rester.y.v + rester.h.v;
}

}  // namespace

namespace {

// A one-way body (semantics §9) is a platform only for a body coming down
// on it: not rising, not dropping through, its feet before the frame's move
// (y − vy + h) at or above the platform's top before its own (y − vy).
bool lands_from_above(const Body& m, const Body& o) {
    return m.vy.v >= 0 && !m.drop_through && (m.y - m.vy + m.h).v <= (o.y - o.vy).v;
}

}  // namespace

uint8_t sensed_side(const Body& a, const Body& b) { return entry_side(a, b); }

uint8_t resolve_pair(Body& a, Body& b, bool a_rests, bool b_rests, const TileGrid* walls) {
    if (a.one_way || b.one_way) {  // it lands, or the two pass through each other
        if (!(a.one_way && b.one_way)) {
            Body& m = a.one_way ? b : a;
            const Body& o = a.one_way ? a : b;
            if (!m.immovable && lands_from_above(m, o)) {
                place(m, false, o.y - m.h, walls);
                m.vy = rebound(m.vy, pair_bounce(a, b));
                return a.one_way ? kSideUp : kSideDown;
            }
        }
        return entry_side(a, b);
    }
    if (a.immovable && b.immovable) return entry_side(a, b);
    const double ox = overlap(a.x, a.w, b.x, b.w);
    const double oy = overlap(a.y, a.h, b.y, b.h);
    const Num bounce = pair_bounce(a, b);
    // The fixed body's side is the opposite of the one pushed off it.
    if (a.immovable) return opposite_side(push_off_immovable(b, a, ox, oy, bounce, walls));
    if (b.immovable) return push_off_immovable(a, b, ox, oy, bounce, walls);
    if (a_rests && lands_on(b, a)) return opposite_side(push_off_immovable(b, a, ox, oy, bounce, walls));
    if (b_rests && lands_on(a, b)) return push_off_immovable(a, b, ox, oy, bounce, walls);
    if (ox < oy) return facing(true, push_apart(a, b, true, ox, bounce, walls));
    return facing(false, push_apart(a, b, false, oy, bounce, walls));
}

namespace {

void all_pairs(std::span<Body> bodies, std::span<const size_t> members, std::span<const uint8_t> resting,
               PairLog* log, SideLog* sides, const TileGrid* walls, Extent* rooms) {
    auto rests = [&](size_t i) { return !resting.empty() && resting[i] != 0; };
    for (size_t a = 0; a < members.size(); ++a)
        for (size_t b = a + 1; b < members.size(); ++b) {
            Body& first = bodies[members[a]];
            Body& second = bodies[members[b]];
            if (!aabb_overlap(first, second)) continue;
            if (const uint8_t side = meet(first, second, rests(members[a]), rests(members[b]), walls)) {
                note_pushed(log, sides, members[a], members[b], side);
                note_rooms(rooms, members[a], first, members[b], second);
            }
        }
}


void run_pairs(ContactScratch& scratch, std::span<Body> bodies, std::span<const size_t> members,
               PairMethod method, std::span<const uint8_t> resting) {
    if (members.size() < 2) return;
    const bool grid = method == PairMethod::Grid ||
                      (method == PairMethod::Auto && members.size() >= kPairGridFrom);
    if (grid) scratch.sweep.run(bodies, members, resting, scratch.log, scratch.sides, scratch.walls, scratch.rooms);
    else all_pairs(bodies, members, resting, scratch.log, scratch.sides, scratch.walls, scratch.rooms);
}

}  // namespace

void resolve_entity_collisions(ContactScratch& scratch, std::span<Body> bodies, PairMethod method,
                               std::span<const uint8_t> resting) {
    // Only solid, non-ghost bodies take part; walking just those, in list
    // order, visits the eligible pairs in exactly the all-pairs order.
    std::vector<size_t>& members = scratch.members;
    members.clear();
    bool reports = false;
    for (size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].collides() || bodies[i].senses()) members.push_back(i);
        reports |= bodies[i].contacts;
    }
    run_pairs(scratch, bodies, members, method, resting);
    if (reports) mark_touching(bodies);
}

void resolve_entity_collisions(std::span<Body> bodies) {
    resolve_entity_collisions_by(bodies, PairMethod::Auto);
}

void resolve_entity_collisions_by(std::span<Body> bodies, PairMethod method,
                                  std::span<const uint8_t> resting) {
    ContactScratch scratch;
    resolve_entity_collisions(scratch, bodies, method, resting);
}

void resolve_entity_collisions_among(ContactScratch& scratch, std::span<Body> bodies,
                                     std::span<const size_t> members,
                                     std::span<const uint8_t> resting) {
    run_pairs(scratch, bodies, members, PairMethod::Auto, resting);
}

}  // namespace ds
