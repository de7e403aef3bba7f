// SPDX-License-Identifier: MIT
#include "tile_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

bool same_points(std::vector<Pt> a, std::vector<Pt> b) {
    auto less = [](Pt p, Pt q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
    std::sort(a.begin(), a.end(), less);
    std::sort(b.begin(), b.end(), less);
    a.erase(std::unique(a.begin(), a.end()), a.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return a == b;
}

// The polygon as a box or as its box cut by its one slanted edge, or the
// whole cell when it is neither.
TileSolidPart classify(const std::vector<Pt>& outline, int64_t tw, int64_t th) {
    TileSolidPart part;
    const std::vector<Pt> pts = simplified(outline);
    if (pts.size() < 3) return part;  // no area: the whole cell, as any other odd shape
    int64_t x0 = pts[0].x, y0 = pts[0].y, x1 = x0, y1 = y0;
    for (const Pt& p : pts) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    std::vector<std::pair<Pt, Pt>> slants;
    for (size_t i = 0; i < pts.size(); ++i) {
        const Pt a = pts[i], b = pts[(i + 1) % pts.size()];
        if (a.x != b.x && a.y != b.y) slants.push_back({a, b});
    }
    const std::vector<Pt> corners = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    CellShape s;
    s.x0 = static_cast<int32_t>(x0), s.y0 = static_cast<int32_t>(y0);
    s.x1 = static_cast<int32_t>(x1), s.y1 = static_cast<int32_t>(y1);
    if (slants.empty()) {
        if (!same_points(pts, corners)) return part;
        if (x0 == 0 && y0 == 0 && x1 == tw && y1 == th) return part;
        part.whole = false;
        part.shape = s;
        return part;
    }
    if (slants.size() != 1) return part;
    Pt p = slants[0].first, q = slants[0].second;
    if (q.x < p.x) std::swap(p, q);
    auto on_edge = [&](Pt a) { return a.x == x0 || a.x == x1 || a.y == y0 || a.y == y1; };
    if (!on_edge(p) || !on_edge(q)) return part;
    // The box cut by the line through p and q has for vertices p, q and the
    // box's corners strictly on the kept side: a floor keeps those below the
    // line (y down, p left of q: cross > 0), a ceiling those above.
    for (const Cut cut : {Cut::Floor, Cut::Ceiling}) {
        std::vector<Pt> kept = {p, q};
        for (const Pt& c : corners) {
            const int64_t side = cross(p, q, c);
            if (cut == Cut::Floor ? side > 0 : side < 0) kept.push_back(c);
        }
        if (!same_points(kept, pts)) continue;
        s.cut = cut;
        s.ax = static_cast<int32_t>(p.x), s.ay = static_cast<int32_t>(p.y);
        s.bx = static_cast<int32_t>(q.x), s.by = static_cast<int32_t>(q.y);
        part.whole = false;
        part.shape = s;
        return part;
    }
    return part;
}

}  // namespace

TileSolidPart tile_solid_part(const std::vector<MapObject>& objects, int tile_w, int tile_h, uint32_t flips) {
    TileSolidPart part;
    if (objects.size() != 1) return part;
    const MapObject& o = objects[0];
    if (o.rotation != 0) return part;
    std::vector<std::pair<double, double>> raw;
    if (o.shape == ObjectShape::Rectangle && o.gid == 0) {
        if (!(o.width > 0 && o.height > 0)) {
            part.problem = "a collision rectangle of " + pt_text(o.width, o.height) + " px has no area";
            return part;
        }
        raw = {{o.x, o.y}, {o.x + o.width, o.y}, {o.x + o.width, o.y + o.height}, {o.x, o.y + o.height}};
    } else if (o.shape == ObjectShape::Polygon) {
        if (o.points.size() < 3) {
            part.problem = "a collision polygon of " + std::to_string(o.points.size()) + " point" +
                           (o.points.size() == 1 ? "" : "s") + " (3 at least make a shape)";
            return part;
        }
        if (o.points.size() > kMaxShapePoints) {
            part.problem = "a collision polygon of " + std::to_string(o.points.size()) + " points, more than the " +
                           std::to_string(kMaxShapePoints) + " a shape may have";
            return part;
        }
        for (const ObjectPoint& p : o.points) raw.push_back({o.x + p.x, o.y + p.y});
    } else {
        return part;
    }
    std::vector<Pt> pts;
    for (const auto& [x, y] : raw) {
        const Pt p{std::llround(x), std::llround(y)};
        if (p.x < 0 || p.y < 0 || p.x > tile_w || p.y > tile_h) {
            part.problem = "collision point " + pt_text(x, y) + " lies outside the " + std::to_string(tile_w) +
                           "x" + std::to_string(tile_h) + " tile";
            return part;
        }
        pts.push_back(turned(p, tile_w, tile_h, flips));
    }
    return classify(pts, tile_w, tile_h);
}

}  // namespace ds
