// SPDX-License-Identifier: MIT
#include "tile_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "../constants.hpp"

namespace ds {

namespace {

struct Pt {
    int64_t x, y;
    bool operator==(const Pt&) const = default;
};

std::string pt_text(double x, double y) {
    auto num = [](double v) {
        std::string s = std::to_string(v);
        s.erase(s.find_last_not_of('0') + 1);
        if (!s.empty() && s.back() == '.') s.pop_back();
        return s;
    };
    return "(" + num(x) + ", " + num(y) + ")";
}

// As Tiled turns a tile: the diagonal flip (a transposition, scaled for a
// tile that is not square) first, then the horizontal and vertical flips.
Pt turned(Pt p, int64_t tw, int64_t th, uint32_t flips) {
    if (flips & kFlipDiagonal) {
        p = tw == th ? Pt{p.y, p.x}
                     : Pt{std::llround(static_cast<double>(p.y) * tw / th),
                          std::llround(static_cast<double>(p.x) * th / tw)};
    }
    if (flips & kFlipHorizontal) p.x = tw - p.x;
    if (flips & kFlipVertical) p.y = th - p.y;
    return p;
}

int64_t cross(Pt o, Pt a, Pt b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// The outline with repeated points and points on a straight run dropped:
// no point left lies on the line through its two neighbours. One pass with
// a stack, then the seam where the outline closes: linear in the points, as
// a shape is met once per distinct gid and flip, not once per cell.
std::vector<Pt> simplified(const std::vector<Pt>& pts) {
    std::vector<Pt> out;
    out.reserve(pts.size());
    for (const Pt& p : pts) {
        while (out.size() >= 2 && cross(out[out.size() - 2], out.back(), p) == 0) out.pop_back();
        out.push_back(p);
    }
    // Every point between the first and the last has its final neighbours;
    // those two are tried against the neighbours across the seam.
    size_t first = 0;
    while (out.size() - first >= 3) {
        if (cross(out[out.size() - 2], out.back(), out[first]) == 0) {
            out.pop_back();
        } else if (cross(out.back(), out[first], out[first + 1]) == 0) {
            ++first;
        } else {
            break;
        }
    }
    out.erase(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(first));
    return out;
}

// A coordinate of a clipped outline, exactly: n / d in lowest terms, d > 0.
// Every one is a polygon point, a cell corner or where a polygon edge (a
// line through two integer points) crosses a cell side, so n and d stay
// products of two coordinates (kMaxShapeReachTiles bounds them).
struct Ratio {
    int64_t n, d;
    bool operator==(const Ratio&) const = default;
};
Ratio ratio(int64_t n, int64_t d) {
    if (d < 0) n = -n, d = -d;
    const int64_t g = std::gcd(n, d);
    return {n / g, d / g};
}
int64_t floor_of(Ratio r) { return r.n >= 0 ? r.n / r.d : -((-r.n + r.d - 1) / r.d); }
int64_t ceil_of(Ratio r) { return -floor_of({-r.n, r.d}); }
bool less(Ratio a, Ratio b) { return static_cast<__int128>(a.n) * b.d < static_cast<__int128>(b.n) * a.d; }

// A corner of the clipped outline and the line the edge arriving at it lies
// on, as two integer points of that line (a polygon edge, in the outline's
// direction, or a cell side).
struct Corner {
    Ratio x, y;
    Pt from, to;
};

bool same_line(const Corner& a, const Corner& b) {
    return cross(a.from, a.to, b.from) == 0 && cross(a.from, a.to, b.to) == 0;
}

// One step of Sutherland–Hodgman: the outline cut by the cell side
// `axis` = c (x when along_x), keeping the side where the coordinate is at
// most c (keep_low) or at least c. From a convex outline, a convex one.
std::vector<Corner> clip_side(const std::vector<Corner>& in, bool along_x, int64_t c, bool keep_low) {
    auto coord = [&](const Corner& v) { return along_x ? v.x : v.y; };
    auto inside = [&](const Corner& v) {
        const Ratio r = coord(v);
        const Ratio k{c, 1};
        return keep_low ? !less(k, r) : !less(r, k);
    };
    const Pt side_from = along_x ? Pt{c, 0} : Pt{0, c}, side_to = along_x ? Pt{c, 1} : Pt{1, c};
    // Where the line of corner `e`'s arriving edge crosses the side.
    auto crossing = [&](const Corner& e, Pt from, Pt to) {
        Corner v{};
        if (along_x) {
            const int64_t d = e.to.x - e.from.x;
            v.x = {c, 1}, v.y = ratio(e.from.y * d + (c - e.from.x) * (e.to.y - e.from.y), d);
        } else {
            const int64_t d = e.to.y - e.from.y;
            v.y = {c, 1}, v.x = ratio(e.from.x * d + (c - e.from.y) * (e.to.x - e.from.x), d);
        }
        v.from = from, v.to = to;
        return v;
    };
    std::vector<Corner> out;
    for (size_t i = 0; i < in.size(); ++i) {
        const Corner& s = in[(i + in.size() - 1) % in.size()];
        const Corner& e = in[i];
        if (inside(e)) {
            if (!inside(s)) out.push_back(crossing(e, side_from, side_to));  // entering: arrived along the side
            out.push_back(e);
        } else if (inside(s)) {
            out.push_back(crossing(e, e.from, e.to));  // leaving: arrived along e's line
        }
    }
    return out;
}

// The outline with repeated corners and corners on a straight run dropped.
std::vector<Corner> tidied(std::vector<Corner> v) {
    for (bool changed = true; changed && v.size() >= 2;) {
        changed = false;
        for (size_t i = 0; i < v.size() && v.size() >= 2; ++i) {
            const size_t j = (i + 1) % v.size();
            if (v[i].x == v[j].x && v[i].y == v[j].y) {
                v.erase(v.begin() + static_cast<std::ptrdiff_t>(j));
                changed = true;
            } else if (same_line(v[i], v[j])) {
                v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
            }
        }
    }
    return v;
}

// Whether the outline (simplified: no repeated points, none on a straight
// run) is convex and winds once; `turn` gets the sign of its turns.
bool convex(const std::vector<Pt>& pts, int& turn) {
    const size_t n = pts.size();
    turn = 0;
    int dx_sign_changes = 0, last_dx = 0;
    for (size_t i = 0; i < n; ++i) {
        const Pt a = pts[i], b = pts[(i + 1) % n], c = pts[(i + 2) % n];
        const int t = cross(a, b, c) > 0 ? 1 : -1;
        if (turn != 0 && t != turn) return false;
        turn = t;
        const int dx = b.x > a.x ? 1 : b.x < a.x ? -1 : 0;
        if (dx != 0) {
            if (last_dx != 0 && dx != last_dx) ++dx_sign_changes;
            last_dx = dx;
        }
    }
    // The edges' x direction turns twice around a convex outline; a star's
    // turns all have one sign too, but it winds more than once.
    for (size_t i = 0; i < n; ++i) {  // the change across the seam
        const Pt a = pts[i], b = pts[(i + 1) % n];
        const int dx = b.x > a.x ? 1 : b.x < a.x ? -1 : 0;
        if (dx != 0) {
            if (dx != last_dx) ++dx_sign_changes;
            break;
        }
    }
    return dx_sign_changes <= 2;
}

// The part of convex outline `pts` (turning `turn`) inside the tw × th
// cell: a box, a shape cut by slants on one side or both, the whole cell or nothing
// (semantics §12). The part inside is the box of its axis-aligned edges cut
// by its slanted edges' lines: the box rounded out to whole px cuts to the
// same part, as only the slants' ends can lie off whole px, and each slant
// keeps the rest of the rounded box out on its side. `what` names the
// object, `reached_out` whether it reached past the tile (for the warning).
TileSolidPart clipped_part(const std::vector<Pt>& pts, int turn, int64_t tw, int64_t th, const char* what,
                           bool reached_out) {
    TileSolidPart part;
    std::vector<Corner> outline;
    for (size_t i = 0; i < pts.size(); ++i) {
        const Pt prev = pts[(i + pts.size() - 1) % pts.size()];
        outline.push_back({{pts[i].x, 1}, {pts[i].y, 1}, prev, pts[i]});
    }
    outline = clip_side(outline, true, 0, false);
    outline = clip_side(outline, true, tw, true);
    outline = clip_side(outline, false, 0, false);
    outline = clip_side(outline, false, th, true);
    outline = tidied(std::move(outline));
    const std::string tile = std::to_string(tw) + "x" + std::to_string(th) + " tile";
    const std::string named =
        reached_out ? std::string("the part of the ") + what + " inside the " + tile : std::string("the ") + what;
    if (outline.size() < 3) {
        part.whole = false, part.empty = true;
        part.problem = named + " has no area";
        return part;
    }
    Ratio x0 = outline[0].x, x1 = x0, y0 = outline[0].y, y1 = y0;
    std::vector<Slant> tops, bottoms;  // the slanted edges on its top and on its underside
    for (const Corner& v : outline) {
        if (less(v.x, x0)) x0 = v.x;
        if (less(x1, v.x)) x1 = v.x;
        if (less(v.y, y0)) y0 = v.y;
        if (less(y1, v.y)) y1 = v.y;
        if (v.from.x == v.to.x || v.from.y == v.to.y) continue;
        Pt p = v.from, q = v.to;
        // The inside lies where cross(from, to, ·) has the outline's turn.
        int kept = turn;
        if (q.x < p.x) std::swap(p, q), kept = -kept;
        (kept > 0 ? tops : bottoms)
            .push_back({static_cast<int32_t>(p.x), static_cast<int32_t>(p.y), static_cast<int32_t>(q.x),
                        static_cast<int32_t>(q.y)});
    }
    for (const auto* side : {&tops, &bottoms}) {
        if (side->size() > static_cast<size_t>(kMaxShapeSlants)) {
            part.problem = named + " has " + std::to_string(side->size()) + " slanted edges on its " +
                           (side == &tops ? "top" : "underside") + ", more than the " +
                           std::to_string(kMaxShapeSlants) + " a shape may have";
            return part;
        }
    }
    // Slanted on one side, the shape keeps that side of its slants; on
    // both, it is a floor shape bounded below by its underside's slants.
    const Cut cut = !tops.empty() ? Cut::Floor : !bottoms.empty() ? Cut::Ceiling : Cut::None;
    std::vector<Slant>& slants = cut == Cut::Floor ? tops : bottoms;
    // Left to right along the boundary they make: a convex outline's edges
    // on one side follow each other along x.
    auto by_x = [](const Slant& a, const Slant& b) { return a.ax < b.ax; };
    CellShape s;
    s.x0 = static_cast<int32_t>(floor_of(x0)), s.y0 = static_cast<int32_t>(floor_of(y0));
    s.x1 = static_cast<int32_t>(ceil_of(x1)), s.y1 = static_cast<int32_t>(ceil_of(y1));
    if (slants.empty() && s.x0 == 0 && s.y0 == 0 && s.x1 == tw && s.y1 == th) return part;
    if (!slants.empty()) {
        std::sort(slants.begin(), slants.end(), by_x);
        s.cut = cut;
        s.ax = slants[0].ax, s.ay = slants[0].ay, s.bx = slants[0].bx, s.by = slants[0].by;
        s.n_more = static_cast<uint8_t>(slants.size() - 1);
        std::copy(slants.begin() + 1, slants.end(), s.more.begin());
    }
    if (cut == Cut::Floor && !bottoms.empty()) {
        std::sort(bottoms.begin(), bottoms.end(), by_x);
        s.n_under = static_cast<uint8_t>(bottoms.size());
        std::copy(bottoms.begin(), bottoms.end(), s.under.begin());
    }
    part.whole = false;
    part.shape = s;
    return part;
}

}  // namespace

TileSolidPart tile_solid_part(const std::vector<MapObject>& objects, int tile_w, int tile_h, uint32_t flips) {
    TileSolidPart part;
    if (objects.size() != 1) return part;
    const MapObject& o = objects[0];
    if (o.rotation != 0) return part;
    auto no_area = [&](std::string why) {
        part.whole = false, part.empty = true;
        part.problem = std::move(why);
        return part;
    };
    std::vector<std::pair<double, double>> raw;
    const char* what = "collision polygon";
    if (o.shape == ObjectShape::Rectangle && o.gid == 0) {
        if (!(o.width > 0 && o.height > 0))
            return no_area("a collision rectangle of " + pt_text(o.width, o.height) + " px has no area");
        what = "collision rectangle";
        raw = {{o.x, o.y}, {o.x + o.width, o.y}, {o.x + o.width, o.y + o.height}, {o.x, o.y + o.height}};
    } else if (o.shape == ObjectShape::Polygon) {
        if (o.points.size() < 3)
            return no_area("a collision polygon of " + std::to_string(o.points.size()) + " point" +
                           (o.points.size() == 1 ? "" : "s") + " (3 at least make a shape)");
        if (o.points.size() > kMaxShapePoints) {
            part.problem = "a collision polygon of " + std::to_string(o.points.size()) + " points, more than the " +
                           std::to_string(kMaxShapePoints) + " a shape may have";
            return part;
        }
        for (const ObjectPoint& p : o.points) raw.push_back({o.x + p.x, o.y + p.y});
    } else {
        return part;
    }
    const std::string tile = std::to_string(tile_w) + "x" + std::to_string(tile_h) + " tile";
    std::vector<Pt> pts;
    std::string outside;  // the first point outside the tile, as written; empty when none
    for (const auto& [x, y] : raw) {
        const double rx = std::round(x), ry = std::round(y);
        const double reach_x = static_cast<double>(kMaxShapeReachTiles) * tile_w;
        const double reach_y = static_cast<double>(kMaxShapeReachTiles) * tile_h;
        if (!(rx >= -reach_x && rx <= tile_w + reach_x && ry >= -reach_y && ry <= tile_h + reach_y)) {
            part.problem = "collision point " + pt_text(x, y) + " lies more than a tile outside the " + tile;
            return part;
        }
        const Pt p{static_cast<int64_t>(rx), static_cast<int64_t>(ry)};
        if (outside.empty() && (p.x < 0 || p.y < 0 || p.x > tile_w || p.y > tile_h)) outside = pt_text(x, y);
        pts.push_back(turned(p, tile_w, tile_h, flips));
    }
    const std::vector<Pt> outline = simplified(pts);
    if (outline.size() < 3) return no_area(std::string("a ") + what + " whose points lie on one line has no area");
    int turn = 0;
    if (!convex(outline, turn)) {
        part.problem = outside.empty() ? std::string("the ") + what + " is not convex"
                                       : "collision point " + outside + " lies outside the " + tile +
                                             " and the polygon is not convex, so its part inside is not read";
        return part;
    }
    return clipped_part(outline, turn, tile_w, tile_h, what, !outside.empty());
}

}  // namespace ds
