// SPDX-License-Identifier: MIT
#include "map_draw.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "constants.hpp"
#include "scene_view.hpp"
#include "tilemap/map_objects.hpp"

namespace ds::render {

namespace {

using cell_math::floor_div;  // every divisor here is a positive size

uint8_t opacity_alpha(double opacity) {
    return static_cast<uint8_t>(std::lround(std::clamp(opacity, 0.0, 1.0) * 255));
}

int clamp_int(int64_t v) { return int(std::clamp<int64_t>(v, -(1 << 30), 1 << 30)); }

// A position in whole px, floored as the camera is; bounded to the range
// where the core's coordinates are exact, so no cast overflows.
int64_t floor_px(double v) {
    constexpr double kExact = 9007199254740992.0;  // 2^53
    if (!(v == v)) return 0;
    return int64_t(std::floor(std::clamp(v, -kExact, kExact)));
}

// A layer's offset (summed through its groups first, as Tiled's
// Layer::totalOffset sums it) in whole px, rounded as Qt's raster engine
// rounds a translated picture's position: halves go up, -1.5 to -1.
double offset_px(double offset) { return std::floor(offset + 0.5); }

bool untinted(Rgba t) { return t.r == 255 && t.g == 255 && t.b == 255 && t.a == 255; }

// The largest tile of any tileset beyond the map's cell, per axis: how far a
// bottom-left aligned tile can reach out of its cell (its tile offset too).
std::pair<int, int> overhang(const Tilemap& map) {
    int w = 0, h = 0;
    for (const Tileset& ts : map.tilesets) {
        const int ox = std::abs(ts.tile_offset_x), oy = std::abs(ts.tile_offset_y);
        w = std::max(w, ts.tile_width - map.tile_width + ox);
        h = std::max(h, ts.tile_height - map.tile_height + oy);
        for (const TileInfo& t : ts.tiles) {  // collection tiles have their own sizes
            w = std::max(w, t.image_width - map.tile_width + ox);
            h = std::max(h, t.image_height - map.tile_height + oy);
        }
    }
    return {w, h};
}

// A cell whose gid no tileset holds (Tiled loads such maps and shows the
// tile as missing): a marker the size of the cell, so the hole is seen.
void draw_missing(Canvas& c, int64_t x, int64_t y, int w, int h, uint8_t alpha) {
    Rgba fill = kMissingTileColor;
    fill.a = uint8_t(alpha * kMissingTileFillAlpha / 255);
    c.fill_rect(clamp_int(x), clamp_int(y), w, h, fill);
    Rgba edge = kMissingTileColor;
    edge.a = alpha;
    c.outline_rect(clamp_int(x), clamp_int(y), w, h, edge);
}

// Whether a gid that has no picture is drawn as a missing tile: one no
// tileset holds, or one of an atlas whose image ends before it (a tilecount
// larger than the image holds; the loader warned of both). A collection's
// tile without an image is drawn as nothing, as Tiled draws it.
bool missing_tile(const Tilemap& map, uint32_t gid) {
    const Tileset* ts = map.tileset_for(gid & kGidMask);
    return !map.gid_known(gid & kGidMask) || (ts && !ts->image.empty());
}

// Where tile picture `pic` (turned by its gid's flips) goes when drawn into
// the box at (x, y), w × h, as Tiled's cell renderer puts it: scaled to the
// box (by the smaller factor, centred, under preserve-aspect-fit), moved by
// the tileset's tile offset at that scale; a diagonal flip turns the
// picture about the box's bottom-left corner.
PictureBox cell_box(const Tileset& ts, SDL_Surface* pic, uint32_t raw_gid, double x, double y, double w, double h) {
    const bool diagonal = raw_gid & kFlipDiagonal;
    const double iw = diagonal ? pic->h : pic->w, ih = diagonal ? pic->w : pic->h;
    double sx = w / iw, sy = h / ih;
    if (ts.fill_mode == FillMode::PreserveAspectFit) sx = sy = std::min(sx, sy);
    PictureBox b;
    b.cx = x + w / 2 + ts.tile_offset_x * sx;
    b.cy = y + h / 2 + ts.tile_offset_y * sy;
    b.w = iw * sx, b.h = ih * sy;
    if (diagonal) {
        const double half_diff = (h - w) / 2;
        b.cx += half_diff, b.cy += half_diff;
        std::swap(b.w, b.h);
    }
    b.reversed_x = raw_gid & kFlipHorizontal, b.reversed_y = raw_gid & kFlipVertical;
    b.transposed = diagonal;
    return b;
}

// Draws a box's picture: copied when it is the picture's own size at whole
// px, unturned and untinted; else through Canvas::draw_picture.
void put_picture(Canvas& c, SDL_Surface* pic, const PictureBox& b, uint8_t alpha, Rgba tint) {
    const double left = b.cx - b.w / 2, top = b.cy - b.h / 2;
    if (b.degrees == 0 && untinted(tint) && b.w == pic->w && b.h == pic->h && left == std::floor(left) &&
        top == std::floor(top) && std::fabs(left) < 1e9 && std::fabs(top) < 1e9) {
        c.blit(pic, int(left), int(top), alpha);
        return;
    }
    c.draw_picture(pic, b, alpha, tint);
}

struct LayerPaint {
    uint8_t alpha;
    Rgba tint;
    LayerCamera cam;
};

size_t draw_tile_layer(Canvas& c, TileArt& art, const Tilemap& map, const TileLayer& layer,
                       const LayerPaint& p, double time_ms) {
    const std::pair<int, int> over = overhang(map);
    const CellWindow w = visible_cells(layer, map.tile_width, map.tile_height, p.cam.x, p.cam.y, c.width(),
                                       c.height(), over.first, over.second);
    const bool up = map.render_order == RenderOrder::RightUp || map.render_order == RenderOrder::LeftUp;
    const bool left = map.render_order == RenderOrder::LeftDown || map.render_order == RenderOrder::LeftUp;
    size_t drawn = 0;
    for (int64_t i = 0; i < w.row1 - w.row0; ++i) {
        const int64_t row = up ? w.row1 - 1 - i : w.row0 + i;
        const size_t first = static_cast<size_t>((row - layer.origin_row) * layer.width - layer.origin_col);
        for (int64_t j = 0; j < w.col1 - w.col0; ++j) {
            const int64_t col = left ? w.col1 - 1 - j : w.col0 + j;
            const uint32_t gid = layer.cells[first + static_cast<size_t>(col)];
            if (!gid) continue;
            const int64_t x = col * map.tile_width - p.cam.x, bottom = (row + 1) * map.tile_height - p.cam.y;
            SDL_Surface* pic = art.tile(gid, time_ms);
            if (!pic) {
                if (missing_tile(map, gid))
                    draw_missing(c, x, bottom - map.tile_height, map.tile_width, map.tile_height, p.alpha);
                continue;
            }
            const Tileset& ts = *map.tileset_for(gid & kGidMask);
            const bool diagonal = gid & kFlipDiagonal;
            double bw = diagonal ? pic->h : pic->w, bh = diagonal ? pic->w : pic->h;
            if (ts.render_size == TileRenderSize::Grid) bw = map.tile_width, bh = map.tile_height;
            put_picture(c, pic, cell_box(ts, pic, gid, double(x), double(bottom) - bh, bw, bh), p.alpha, p.tint);
            ++drawn;
        }
    }
    return drawn;
}

// An object layer's tile objects (shapes and text are the game's, not
// drawn), in its draw order: the file's, or by y for draworder="topdown".
size_t draw_object_layer(Canvas& c, TileArt& art, const Tilemap& map, const ObjectLayer& layer,
                         const LayerPaint& p, double time_ms) {
    // The objects to visit, in draw order: those the index finds in view,
    // else (a layer made by hand, or edited since) every one.
    static thread_local std::vector<uint32_t> ranks;
    const std::vector<uint32_t>* order = &layer.index.order;
    if (layer.index.built && layer.index.order.size() == layer.objects.size()) {
        objects_in_view(layer.index, double(p.cam.x), double(p.cam.y), double(p.cam.x) + c.width(),
                        double(p.cam.y) + c.height(), ranks);
    } else {
        static thread_local std::vector<uint32_t> all;
        all = object_draw_order(layer);
        order = &all;
        ranks.resize(all.size());
        std::iota(ranks.begin(), ranks.end(), 0u);
    }
    size_t drawn = 0;
    for (uint32_t rank : ranks) {
        const MapObject& o = layer.objects[(*order)[rank]];
        if (!o.visible || o.shape != ObjectShape::Tile) continue;
        const TileObjectBox box = tile_object_box(map, o);
        SDL_Surface* pic = art.tile(o.gid, time_ms);
        const Tileset* ts = map.tileset_for(o.gid & kGidMask);
        const double x = box.left - double(p.cam.x), y = box.top - double(p.cam.y);
        if (!map.gid_known(o.gid & kGidMask) || (!pic && missing_tile(map, o.gid))) {  // the loader warned of it
            const int w = box.width > 0 ? int(std::min(box.width, 4096.0)) : map.tile_width;
            const int h = box.height > 0 ? int(std::min(box.height, 4096.0)) : map.tile_height;
            draw_missing(c, floor_px(x), floor_px(box.height > 0 ? y : y - h), w, h, p.alpha);
            continue;
        }
        if (!pic || !ts) continue;
        PictureBox b = cell_box(*ts, pic, o.gid, x, y, box.width, box.height);
        b.degrees = box.rotation;
        b.pivot_x = box.pivot_x - double(p.cam.x), b.pivot_y = box.pivot_y - double(p.cam.y);
        put_picture(c, pic, b, p.alpha, p.tint);
        ++drawn;
    }
    return drawn;
}

// An image layer's picture at the layer's origin, repeated along the axes
// it repeats on to fill the canvas.
size_t draw_image_layer(Canvas& c, TileArt& art, const Tilemap& map, const LayerInfo& info, const LayerPaint& p) {
    if (info.image.empty()) return 0;
    SDL_Surface* pic = art.picture(layer_image_path(map, info.image), info.image_trans, info.image_width,
                                   info.image_height);
    if (!pic || pic->w <= 0 || pic->h <= 0) return 0;
    const auto first = [](int64_t origin, int64_t size, bool repeat) {
        return repeat ? origin - floor_div(origin, size) * size - size : origin;
    };
    const int64_t x0 = first(-p.cam.x, pic->w, info.repeat_x), y0 = first(-p.cam.y, pic->h, info.repeat_y);
    const int64_t x1 = info.repeat_x ? c.width() : x0 + 1, y1 = info.repeat_y ? c.height() : y0 + 1;
    size_t drawn = 0;
    for (int64_t y = y0; y < y1; y += pic->h)
        for (int64_t x = x0; x < x1; x += pic->w) {
            if (x >= c.width() || y >= c.height() || x + pic->w <= 0 || y + pic->h <= 0) continue;
            put_picture(c, pic, PictureBox{double(x) + pic->w / 2.0, double(y) + pic->h / 2.0, double(pic->w), double(pic->h)},
                        p.alpha, p.tint);
            ++drawn;
        }
    return drawn;
}

void flatten(const std::vector<LayerInfo>& tree, const DrawnLayer& parent, std::vector<DrawnLayer>& out) {
    for (const LayerInfo& info : tree) {
        DrawnLayer d = parent;
        d.info = &info;
        d.kind = info.kind, d.index = info.index;
        d.visible = parent.visible && info.visible;
        d.opacity = parent.opacity * info.opacity;
        d.offset_x = parent.offset_x + info.offset_x, d.offset_y = parent.offset_y + info.offset_y;
        d.parallax_x = parent.parallax_x * info.parallax_x, d.parallax_y = parent.parallax_y * info.parallax_y;
        if (info.tint)
            d.tint = {mul255(d.tint.r, info.tint->r), mul255(d.tint.g, info.tint->g), mul255(d.tint.b, info.tint->b),
                      mul255(d.tint.a, info.tint->a)};
        if (info.kind == LayerKind::Group) flatten(info.children, d, out);
        else out.push_back(d);
    }
}

}  // namespace

CellWindow visible_cells(const TileLayer& layer, int tile_w, int tile_h, int64_t view_x,
                         int64_t view_y, int view_w, int view_h, int over_w, int over_h) {
    CellWindow w;
    if (tile_w <= 0 || tile_h <= 0) return w;
    w.col0 = std::max(layer.origin_col, floor_div(view_x - over_w, tile_w));
    w.col1 = std::min(layer.origin_col + layer.width, floor_div(view_x + view_w - 1 + over_w, tile_w) + 1);
    w.row0 = std::max(layer.origin_row, floor_div(view_y - over_h, tile_h));
    w.row1 = std::min(layer.origin_row + layer.height, floor_div(view_y + view_h - 1 + over_h, tile_h) + 1);
    if (w.col1 < w.col0) w.col1 = w.col0;
    if (w.row1 < w.row0) w.row1 = w.row0;
    return w;
}

std::vector<DrawnLayer> drawn_layers(const Tilemap& map) {
    std::vector<DrawnLayer> out;
    flatten(map.layer_tree, DrawnLayer{}, out);
    if (map.layer_tree.empty())
        for (size_t i = 0; i < map.layers.size(); ++i) {
            const TileLayer& l = map.layers[i];
            out.push_back({.kind = LayerKind::Tile, .index = i, .visible = l.visible, .opacity = l.opacity,
                           .offset_x = l.offset_x, .offset_y = l.offset_y});
        }
    return out;
}

LayerCamera layer_camera(const Tilemap& map, const DrawnLayer& l, int64_t cam_x, int64_t cam_y, int view_w,
                         int view_h) {
    const double centre_x = double(cam_x) + view_w / 2.0, centre_y = double(cam_y) + view_h / 2.0;
    const double shift_x = (1 - l.parallax_x) * (centre_x - map.parallax_origin_x);
    const double shift_y = (1 - l.parallax_y) * (centre_y - map.parallax_origin_y);
    // No parallax: whole px stay whole, so the common case is exact.
    const double ox = offset_px(l.offset_x), oy = offset_px(l.offset_y);
    return {l.parallax_x == 1 ? cam_x - floor_px(ox) : floor_px(double(cam_x) - shift_x - ox),
            l.parallax_y == 1 ? cam_y - floor_px(oy) : floor_px(double(cam_y) - shift_y - oy)};
}

size_t draw_layers(Canvas& c, TileArt& art, const Tilemap& map, std::span<const DrawnLayer> layers, int64_t cam_x,
                   int64_t cam_y, double time_ms) {
    size_t drawn = 0;
    for (const DrawnLayer& l : layers) {
        if (!l.visible || !(l.opacity > 0) || l.tint.a == 0) continue;
        const LayerPaint p{opacity_alpha(l.opacity), l.tint, layer_camera(map, l, cam_x, cam_y, c.width(), c.height())};
        switch (l.kind) {
            case LayerKind::Tile:
                if (l.index < map.layers.size()) drawn += draw_tile_layer(c, art, map, map.layers[l.index], p, time_ms);
                break;
            case LayerKind::Object:
                if (l.index < map.object_layers.size())
                    drawn += draw_object_layer(c, art, map, map.object_layers[l.index], p, time_ms);
                break;
            case LayerKind::Image:
                if (l.info) drawn += draw_image_layer(c, art, map, *l.info, p);
                break;
            case LayerKind::Group: break;
        }
    }
    return drawn;
}

size_t draw_map(Canvas& c, TileArt& art, const Tilemap& map, int64_t cam_x, int64_t cam_y, double time_ms) {
    const std::vector<DrawnLayer> layers = drawn_layers(map);
    return draw_layers(c, art, map, layers, cam_x, cam_y, time_ms);
}

}  // namespace ds::render
