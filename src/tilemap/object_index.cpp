// SPDX-License-Identifier: MIT
#include "object_index.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "map_objects.hpp"
#include "tilemap.hpp"

namespace ds {

namespace {

// A bucket's side: a 640 × 360 view touches at most 4 × 3 of them, and a
// map of 2,000 objects over 16,000² px has a few objects per bucket.
constexpr double kObjectBucketPx = 256;
// The most buckets an index holds: past it the buckets grow, so objects
// spread over an enormous area cost memory in proportion to their number.
constexpr int64_t kMaxObjectBuckets = int64_t(1) << 20;

struct Bounds {
    double x0, y0, x1, y1;
};

// Where an object's picture can reach: its box turned about its anchor,
// moved by its tileset's tile offset at the box's scale (generously: the
// offset's full size in each direction it could apply), plus a pixel.
Bounds drawn_bounds(const Tilemap& map, const MapObject& o) {
    const TileObjectBox b = tile_object_box(map, o);
    const Tileset* ts = map.tileset_for(o.gid & kGidMask);
    const auto [pw, ph] = tile_picture_size(map, o.gid);
    const double sx = pw > 0 ? b.width / pw : 1, sy = ph > 0 ? b.height / ph : 1;
    const double ox = ts ? std::fabs(ts->tile_offset_x * sx) : 0, oy = ts ? std::fabs(ts->tile_offset_y * sy) : 0;
    // A diagonal flip turns the picture about the box's bottom-left: it can
    // reach as far as the box's larger side from there.
    // A gid no tileset holds is drawn as a missing tile of the map's cell size.
    const double reach = std::max({b.width, b.height, double(map.tile_width), double(map.tile_height)});
    double x0 = b.left - ox, y0 = b.top - oy - reach, x1 = b.left + reach + ox, y1 = b.top + b.height + oy;
    if (b.rotation != 0) {  // any turn stays within the circle about the anchor through the far corner
        double r = 0;
        for (const double x : {x0, x1})
            for (const double y : {y0, y1}) r = std::max(r, std::hypot(x - b.pivot_x, y - b.pivot_y));
        x0 = b.pivot_x - r, y0 = b.pivot_y - r, x1 = b.pivot_x + r, y1 = b.pivot_y + r;
    }
    // Ordered, whatever the box's signs: the index sizes its grid of buckets
    // from these, and a box upside down would give it none (the loader
    // refuses negative sizes; the index does not rely on it).
    return {std::min(x0, x1) - 1, std::min(y0, y1) - 1, std::max(x0, x1) + 1, std::max(y0, y1) + 1};
}

bool finite(const Bounds& b) { return std::isfinite(b.x0) && std::isfinite(b.y0) && std::isfinite(b.x1) && std::isfinite(b.y1); }

}  // namespace

std::vector<uint32_t> object_draw_order(const ObjectLayer& layer) {
    std::vector<uint32_t> order(layer.objects.size());
    std::iota(order.begin(), order.end(), 0u);
    if (layer.top_down)
        std::stable_sort(order.begin(), order.end(),
                         [&](uint32_t a, uint32_t b) { return layer.objects[a].y < layer.objects[b].y; });
    return order;
}

ObjectIndex index_objects(const Tilemap& map, const ObjectLayer& layer) {
    ObjectIndex ix;
    ix.built = true;
    ix.order = object_draw_order(layer);
    std::vector<Bounds> bounds(ix.order.size());
    Bounds all{1e300, 1e300, -1e300, -1e300};
    for (size_t rank = 0; rank < ix.order.size(); ++rank) {
        const MapObject& o = layer.objects[ix.order[rank]];
        if (o.shape != ObjectShape::Tile) continue;
        const Bounds b = drawn_bounds(map, o);
        if (!finite(b)) continue;
        bounds[rank] = b;
        all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
    }
    if (all.x0 > all.x1) {  // no tile objects
        ix.starts.assign(1, 0);
        return ix;
    }
    ix.left = all.x0, ix.top = all.y0, ix.bucket = kObjectBucketPx;
    // In doubles until the spans are small: objects may lie ±1e300 px apart
    // (the fuzzer's maps), far past any integer.
    const auto span = [&](double lo, double hi) { return std::floor((hi - lo) / ix.bucket) + 1; };
    while (span(all.x0, all.x1) * span(all.y0, all.y1) > double(kMaxObjectBuckets)) ix.bucket *= 2;
    ix.cols = int64_t(span(all.x0, all.x1)), ix.rows = int64_t(span(all.y0, all.y1));
    const auto cell = [&](double v, double lo, int64_t n) {
        return int64_t(std::clamp(std::floor((v - lo) / ix.bucket), 0.0, double(n - 1)));
    };
    // Counting pass, then filling: two walks over each object's buckets.
    std::vector<uint32_t> count(size_t(ix.cols * ix.rows) + 1, 0);
    const auto each_bucket = [&](const Bounds& b, auto&& fn) {
        for (int64_t r = cell(b.y0, ix.top, ix.rows); r <= cell(b.y1, ix.top, ix.rows); ++r)
            for (int64_t c = cell(b.x0, ix.left, ix.cols); c <= cell(b.x1, ix.left, ix.cols); ++c)
                fn(size_t(r * ix.cols + c));
    };
    for (size_t rank = 0; rank < bounds.size(); ++rank)
        if (layer.objects[ix.order[rank]].shape == ObjectShape::Tile && finite(bounds[rank]))
            each_bucket(bounds[rank], [&](size_t k) { ++count[k + 1]; });
    std::partial_sum(count.begin(), count.end(), count.begin());
    ix.starts = count;
    ix.items.resize(ix.starts.back());
    for (size_t rank = 0; rank < bounds.size(); ++rank)
        if (layer.objects[ix.order[rank]].shape == ObjectShape::Tile && finite(bounds[rank]))
            each_bucket(bounds[rank], [&](size_t k) { ix.items[count[k]++] = uint32_t(rank); });
    return ix;
}

void objects_in_view(const ObjectIndex& ix, double x0, double y0, double x1, double y1, std::vector<uint32_t>& out) {
    out.clear();
    if (ix.cols == 0 || x1 <= ix.left || y1 <= ix.top) return;
    const double right = ix.left + double(ix.cols) * ix.bucket, bottom = ix.top + double(ix.rows) * ix.bucket;
    if (x0 >= right || y0 >= bottom) return;
    const auto cell = [&](double v, double lo, int64_t n) {
        return std::clamp<int64_t>(int64_t(std::floor((v - lo) / ix.bucket)), 0, n - 1);
    };
    const int64_t c0 = cell(x0, ix.left, ix.cols), c1 = cell(x1, ix.left, ix.cols);
    const int64_t r0 = cell(y0, ix.top, ix.rows), r1 = cell(y1, ix.top, ix.rows);
    for (int64_t r = r0; r <= r1; ++r)
        for (int64_t c = c0; c <= c1; ++c) {
            const size_t k = size_t(r * ix.cols + c);
            out.insert(out.end(), ix.items.begin() + ix.starts[k], ix.items.begin() + ix.starts[k + 1]);
        }
    if (c0 != c1 || r0 != r1) {  // an object in two buckets is listed twice
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }
}

}  // namespace ds
