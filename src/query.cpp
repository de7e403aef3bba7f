// SPDX-License-Identifier: MIT
#include "query.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "constants.hpp"
#include "contacts.hpp"
#include "detail/cell_hash.hpp"
#include "detail/placed_shape.hpp"

namespace ds {

namespace {

bool overlap(const Box& a, const Box& b) { return aabb_overlap(a.x, a.y, a.w, a.h, b.x, b.y, b.w, b.h); }

constexpr double kInf = std::numeric_limits<double>::infinity();

// The times t at which p + t·d lies in [lo, hi): from t_in to t_out, or all
// t (−∞, ∞) or none (∞, −∞) when d is 0.
struct Span {
    double in, out;
};
Span axis_span(double p, double d, double lo, double hi) {
    if (d > 0) return {(lo - p) / d, (hi - p) / d};
    if (d < 0) return {(hi - p) / d, (lo - p) / d};
    return lo <= p && p < hi ? Span{-kInf, kInf} : Span{kInf, -kInf};
}

int face(double d) { return d > 0 ? -1 : 1; }

// The hit on the box [lo, hi) × … entered at time t through the faces whose
// span begins at t.
RayHit hit_at(const Segment& s, double t, Span sx, Span sy, double xlo, double xhi, double ylo,
              double yhi) {
    const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    RayHit h;
    h.t = t;
    h.x = s.x0 + t * dx;
    h.y = s.y0 + t * dy;
    if (dx != 0 && sx.in == t) h.nx = face(dx), h.x = dx > 0 ? xlo : xhi;
    if (dy != 0 && sy.in == t) h.ny = face(dy), h.y = dy > 0 ? ylo : yhi;
    return h;
}

}  // namespace

void query_rect(std::span<const Box> boxes, const Box& r, std::vector<uint32_t>& out) {
    for (size_t i = 0; i < boxes.size(); ++i)
        if (overlap(boxes[i], r)) out.push_back(static_cast<uint32_t>(i));
}

void query_point(std::span<const Box> boxes, double px, double py, std::vector<uint32_t>& out) {
    for (size_t i = 0; i < boxes.size(); ++i)
        if (box_contains(boxes[i], px, py)) out.push_back(static_cast<uint32_t>(i));
}

namespace {

CellBox cells_covered(const Box& b, double inv) {
    return {cell_index(b.x, inv), cell_index(b.y, inv), cell_index(b.x + b.w, inv),
            cell_index(b.y + b.h, inv)};
}
uint64_t cell_count(const CellBox& c) {
    return static_cast<uint64_t>(c.x1 - c.x0 + 1) * static_cast<uint64_t>(c.y1 - c.y0 + 1);
}

template <class Visit>
void each_bucket(const CellBox& c, size_t mask, Visit&& visit) {
    for (int64_t cy = c.y0; cy <= c.y1; ++cy)
        for (int64_t cx = c.x0; cx <= c.x1; ++cx) visit(cell_bucket(cx, cy, mask));
}

}  // namespace

void overlapping_pairs(std::span<const Box> a, std::span<const Box> b, SharedMembers shared,
                       PairQueryScratch& s, std::vector<std::pair<uint32_t, uint32_t>>& out) {
    if (a.empty() || b.empty()) return;
    const double inv = inverse_cell_size(b.size(), s.sizes, [&](size_t k) { return std::max(b[k].w, b[k].h); });
    const size_t buckets = std::bit_ceil(2 * b.size());
    const size_t mask = buckets - 1;
    // b's boxes by bucket (counting sort); a box over too many cells is kept
    // aside and tried against every a instead.
    s.bucket_start.assign(buckets + 1, 0);
    for (size_t j = 0; j < b.size(); ++j) {
        const CellBox c = cells_covered(b[j], inv);
        if (cell_count(c) > kQueryMaxCellsPerBox) continue;
        each_bucket(c, mask, [&](size_t k) { ++s.bucket_start[k + 1]; });
    }
    for (size_t k = 0; k < buckets; ++k) s.bucket_start[k + 1] += s.bucket_start[k];
    s.bucket_items.resize(s.bucket_start[buckets]);
    s.seen.assign(b.size(), 0);  // by b: the last a (index + 1) that took it
    s.cursor.assign(s.bucket_start.begin(), s.bucket_start.end() - 1);
    s.oversized.clear();
    for (size_t j = 0; j < b.size(); ++j) {
        const CellBox c = cells_covered(b[j], inv);
        if (cell_count(c) > kQueryMaxCellsPerBox) {
            s.oversized.push_back(static_cast<uint32_t>(j));
            continue;
        }
        each_bucket(c, mask, [&](size_t k) { s.bucket_items[s.cursor[k]++] = static_cast<uint32_t>(j); });
    }
    std::vector<uint32_t>& cands = s.candidates;
    for (size_t i = 0; i < a.size(); ++i) {
        cands.clear();
        const auto stamp = static_cast<uint32_t>(i + 1);
        auto take = [&](uint32_t j) {
            if (s.seen[j] != stamp) s.seen[j] = stamp, cands.push_back(j);
        };
        const CellBox c = cells_covered(a[i], inv);
        if (cell_count(c) > kQueryMaxCellsPerBox) {
            for (uint32_t j = 0; j < b.size(); ++j) take(j);
        } else {
            each_bucket(c, mask, [&](size_t k) {
                for (uint32_t p = s.bucket_start[k]; p < s.bucket_start[k + 1]; ++p) take(s.bucket_items[p]);
            });
            for (const uint32_t j : s.oversized) take(j);
        }
        std::sort(cands.begin(), cands.end());
        const int32_t self = shared.a_in_b.empty() ? -1 : shared.a_in_b[i];
        for (const uint32_t j : cands) {
            if (static_cast<int32_t>(j) == self || !overlap(a[i], b[j])) continue;
            // Both boxes in both sets: the pair is also (b_in_a[j], self).
            const int32_t other = shared.b_in_a.empty() ? -1 : shared.b_in_a[j];
            if (self >= 0 && other >= 0 && other < static_cast<int32_t>(i)) continue;
            out.emplace_back(static_cast<uint32_t>(i), j);
        }
    }
}

void raycast_boxes(std::span<const Box> boxes, const Segment& s, std::vector<RayHit>& out) {
    const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Box& b = boxes[i];
        if (box_contains(b, s.x0, s.y0)) continue;
        const Span sx = axis_span(s.x0, dx, b.x, b.x + b.w);
        const Span sy = axis_span(s.y0, dy, b.y, b.y + b.h);
        const double t = std::max({sx.in, sy.in, 0.0});
        if (!(t < std::min({sx.out, sy.out, 1.0}))) continue;
        RayHit h = hit_at(s, t, sx, sy, b.x, b.x + b.w, b.y, b.y + b.h);
        h.body = static_cast<int64_t>(i);
        out.push_back(h);
    }
}

namespace {

// Where the segment enters the solid of shape p (semantics §8, §12): the
// least t in [0, t_end) with the point in its box and on the kept side of
// every slant; the normal of the face it came through (for the slant, the
// signs of its outward normal). False when it does not, or when the start
// point is inside.
bool ray_into_shape(const shape_math::Placed& p, const Segment& s, double t_end, RayHit& h) {
    if (p.holds(s.x0, s.y0)) return false;
    const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    const Span sx = axis_span(s.x0, dx, p.left(), p.right());
    const Span sy = axis_span(s.y0, dy, p.box_top(), p.box_bottom());
    double in = std::max({sx.in, sy.in, 0.0}), out = std::min({sx.out, sy.out, t_end});
    int through = -1;  // the slant the segment came in through, or −1
    // The slants in turn, a two-sided shape's underside after its top's.
    const int n_top = p.s.cut != Cut::None ? p.lines() : 0, n = n_top + p.under_lines();
    auto slant = [&](int i) { return i < n_top ? p.s.slant(i) : p.s.under[static_cast<size_t>(i - n_top)]; };
    auto kept_below = [&](int i) { return i < n_top && p.s.cut == Cut::Floor; };  // a top's slant
    for (int i = 0; i < n; ++i) {
        // f(t) = sign·(run·(y − ay) − rise·(x − ax)) along the segment: the
        // kept side of slant i is f ≥ 0, and f is linear in t.
        const double sign = kept_below(i) ? 1.0 : -1.0;  // which side of the slant is kept
        const Slant l = slant(i);
        const double run = l.bx - l.ax, rise = l.by - l.ay;
        const double ax = p.ox + l.ax, ay = p.oy + l.ay;
        const double a = sign * (run * (s.y0 - ay) - rise * (s.x0 - ax));
        const double b = sign * (run * dy - rise * dx);
        if (b > 0) {
            const double t = -a / b;
            if (t > in) in = t, through = i;
        } else if (b < 0) {
            out = std::min(out, -a / b);
        } else if (a < 0) {
            return false;
        }
    }
    if (!(in < out)) return false;
    h = hit_at(s, in, sx, sy, p.left(), p.right(), p.box_top(), p.box_bottom());
    if (through >= 0) {
        const Slant l = slant(through);
        const double sign = kept_below(through) ? 1.0 : -1.0;
        h.nx = (l.by - l.ay) * sign > 0 ? 1 : -1;  // outward: (rise, −run) for a floor ramp
        h.ny = kept_below(through) ? -1 : 1;
        h.x = s.x0 + in * dx, h.y = s.y0 + in * dy;
    }
    return true;
}

}  // namespace

void raycast_cells(const TileGrid& grid, const Segment& s, bool first_only, std::vector<RayHit>& out) {
    const double tw = grid.tile_width(), th = grid.tile_height();
    const int64_t c_lo = grid.origin_col(), c_hi = c_lo + grid.cols() - 1;
    const int64_t r_lo = grid.origin_row(), r_hi = r_lo + grid.rows() - 1;
    if (c_hi < c_lo || r_hi < r_lo) return;
    const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    auto edge_x = [&](int64_t c) { return static_cast<double>(c) * tw; };
    auto edge_y = [&](int64_t r) { return static_cast<double>(r) * th; };
    // Only the part of the segment inside the grid is walked.
    const Span gx = axis_span(s.x0, dx, edge_x(c_lo), edge_x(c_hi + 1));
    const Span gy = axis_span(s.y0, dy, edge_y(r_lo), edge_y(r_hi + 1));
    const double t0 = std::max({gx.in, gy.in, 0.0});
    const double t_end = std::min({gx.out, gy.out, 1.0});
    if (!(t0 < t_end)) return;
    // A shaped cell is hit where the segment enters its shape, which may be
    // inside the cell the segment starts in, or past where it enters a cell.
    auto shape_hit = [&](int64_t col, int64_t row) {
        const CellShape* shape = grid.shape(col, row);
        if (!shape || shape->one_way) return false;
        RayHit h;
        if (!ray_into_shape(shape_math::Placed(*shape, col, row, grid), s, t_end, h)) return false;
        h.col = col, h.row = row;
        out.push_back(h);
        return true;
    };
    int64_t c, r;
    if (t0 == 0) {  // the start cell itself is not entered, but its shape may be
        c = static_cast<int64_t>(std::floor(s.x0 / tw));
        r = static_cast<int64_t>(std::floor(s.y0 / th));
        if (shape_hit(c, r) && first_only) return;
    } else {  // entering the grid: the cell at its edge
        c = std::clamp(static_cast<int64_t>(std::floor((s.x0 + t0 * dx) / tw)), c_lo, c_hi);
        r = std::clamp(static_cast<int64_t>(std::floor((s.y0 + t0 * dy) / th)), r_lo, r_hi);
        if (dx != 0 && gx.in == t0) c = dx > 0 ? c_lo : c_hi;
        if (dy != 0 && gy.in == t0) r = dy > 0 ? r_lo : r_hi;
        if (grid.solid(c, r)) {
            RayHit h = hit_at(s, t0, gx, gy, edge_x(c), edge_x(c + 1), edge_y(r), edge_y(r + 1));
            h.col = c, h.row = r;
            out.push_back(h);
            if (first_only) return;
        } else if (shape_hit(c, r) && first_only) {
            return;
        }
    }
    // The next column and row edges the segment crosses, and when.
    auto next_x = [&] { return dx > 0 ? (edge_x(c + 1) - s.x0) / dx : dx < 0 ? (edge_x(c) - s.x0) / dx : kInf; };
    auto next_y = [&] { return dy > 0 ? (edge_y(r + 1) - s.y0) / dy : dy < 0 ? (edge_y(r) - s.y0) / dy : kInf; };
    double tx = next_x(), ty = next_y();
    for (;;) {
        const double t = std::min(tx, ty);
        if (!(t < t_end)) return;
        RayHit h;
        h.t = t;
        h.x = s.x0 + t * dx;
        h.y = s.y0 + t * dy;
        if (tx == t) {  // at a corner both edges are crossed at once
            c += dx > 0 ? 1 : -1;
            h.nx = face(dx), h.x = dx > 0 ? edge_x(c) : edge_x(c + 1);
            tx = next_x();
        }
        if (ty == t) {
            r += dy > 0 ? 1 : -1;
            h.ny = face(dy), h.y = dy > 0 ? edge_y(r) : edge_y(r + 1);
            ty = next_y();
        }
        if (grid.solid(c, r)) {
            h.col = c, h.row = r;
            out.push_back(h);
            if (first_only) return;
        } else if (shape_hit(c, r) && first_only) {
            return;
        }
    }
}

void sort_hits(std::vector<RayHit>& hits) {
    std::stable_sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) {
        if (a.t != b.t) return a.t < b.t;
        return (a.body >= 0) > (b.body >= 0);
    });
}

}  // namespace ds
