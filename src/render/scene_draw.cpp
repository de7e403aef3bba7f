#include "scene_draw.hpp"

#include <algorithm>
#include <cmath>

#include "constants.hpp"
#include "font.hpp"

namespace ds::render {

namespace {

int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

// A picture's size and blend depend on the tile; the layer's opacity fades it.
uint8_t opacity_alpha(double opacity) {
    return static_cast<uint8_t>(std::lround(std::clamp(opacity, 0.0, 1.0) * 255));
}

// The largest tile of any tileset beyond the map's cell, per axis: how far a
// bottom-left aligned tile can reach out of its cell.
std::pair<int, int> overhang(const Tilemap& map) {
    int w = 0, h = 0;
    for (const Tileset& ts : map.tilesets) {
        w = std::max(w, ts.tile_width - map.tile_width);
        h = std::max(h, ts.tile_height - map.tile_height);
        for (const TileInfo& t : ts.tiles) {  // collection tiles have their own sizes
            w = std::max(w, t.image_width - map.tile_width);
            h = std::max(h, t.image_height - map.tile_height);
        }
    }
    return {w, h};
}

Rgba role_color(const EntityView& e) {
    if (e.immovable && e.solid) return kImmovableColor;
    if (e.solid && e.ghost) return kGhostColor;
    if (e.on_ground && e.vx == 0 && e.vy == 0) return kRestingColor;
    return e.solid ? kSolidColor : kPlainColor;
}

struct Box {
    int64_t left, top, w, h;
};
Box screen_box(const EntityView& e, int64_t cx, int64_t cy) {
    const int64_t left = pixel_of(e.x), top = pixel_of(e.y);
    return {left - cx, top - cy, pixel_of(e.x + e.w) - left, pixel_of(e.y + e.h) - top};
}

int clamp_int(int64_t v) { return int(std::clamp<int64_t>(v, -(1 << 30), 1 << 30)); }

void draw_box(Canvas& c, const Box& b, Rgba color) {
    Rgba fill = color;
    fill.a = kBoxFillAlpha;
    c.fill_rect(clamp_int(b.left), clamp_int(b.top), clamp_int(b.w), clamp_int(b.h), fill);
    c.outline_rect(clamp_int(b.left), clamp_int(b.top), clamp_int(b.w), clamp_int(b.h), color);
}

// A box more than this far off the canvas cannot show: skipped before any
// work, so entities far from the view cost one comparison.
bool off_canvas(const Canvas& c, const Box& b, int margin) {
    return b.left + b.w + margin < 0 || b.top + b.h + margin < 0 || b.left - margin > c.width() ||
           b.top - margin > c.height();
}

void draw_entities(Canvas& c, TileArt& art, const SceneView& v, int64_t cx, int64_t cy,
                   DrawCounts& n) {
    for (const EntityView& e : v.entities) {
        const Box b = screen_box(e, cx, cy);
        if (off_canvas(c, b, 256)) continue;
        SDL_Surface* pic = e.sprite ? art.tile(e.sprite ^ (e.flip_x ? kFlipHorizontal : 0), v.time_ms) : nullptr;
        if (pic) {
            c.blit(pic, clamp_int(b.left + (b.w - pic->w) / 2), clamp_int(b.top + b.h - pic->h));
            ++n.sprites;
        } else {
            draw_box(c, b, role_color(e));
            ++n.boxes;
        }
    }
}

void draw_command(Canvas& c, TileArt& art, const DrawCommand& d, int64_t cx, int64_t cy, double time_ms) {
    const int64_t ox = d.space == Space::World ? cx : 0, oy = d.space == Space::World ? cy : 0;
    const int x = clamp_int(pixel_of(d.x) - ox), y = clamp_int(pixel_of(d.y) - oy);
    switch (d.kind) {
        case DrawCommand::Kind::Rect:
        case DrawCommand::Kind::FilledRect: {
            const int w = clamp_int(pixel_of(d.x + d.x2) - pixel_of(d.x));
            const int h = clamp_int(pixel_of(d.y + d.y2) - pixel_of(d.y));
            if (d.kind == DrawCommand::Kind::Rect) c.outline_rect(x, y, w, h, d.color);
            else c.fill_rect(x, y, w, h, d.color);
            break;
        }
        case DrawCommand::Kind::Line:
            c.line(x, y, clamp_int(pixel_of(d.x2) - ox), clamp_int(pixel_of(d.y2) - oy), d.color);
            break;
        case DrawCommand::Kind::Sprite:
            c.blit(art.tile(d.gid, time_ms), x, y);
            break;
        case DrawCommand::Kind::Text:
            c.text(x, y, d.text, d.color, d.scale);
            break;
    }
}

std::pair<int, int> centre(const EntityView& e, int64_t cx, int64_t cy) {
    return {clamp_int(pixel_of(e.x + e.w / 2) - cx), clamp_int(pixel_of(e.y + e.h / 2) - cy)};
}

void draw_legend(Canvas& c) {
    const std::pair<const char*, Rgba> roles[] = {{"solid", kSolidColor},   {"immovable", kImmovableColor},
                                                  {"ghost", kGhostColor},   {"plain", kPlainColor},
                                                  {"resting", kRestingColor}};
    // Along the bottom edge, where a HUD is least often drawn, on a dark
    // plate so it reads over the ground.
    int x = 2;
    const int y = c.height() - kLineHeight;
    int width = 0;
    for (const auto& [name, color] : roles) width += (int(std::char_traits<char>::length(name)) + 1) * kGlyphAdvance;
    c.fill_rect(0, y - 1, width + 2, kLineHeight + 1, kLegendPlate);
    for (const auto& [name, color] : roles) {
        c.text(x, y, name, color);
        x += (int(std::char_traits<char>::length(name)) + 1) * kGlyphAdvance;
    }
}

void draw_overlay(Canvas& c, const SceneView& v, int64_t cx, int64_t cy) {
    for (const Trail& t : v.trails)
        for (size_t i = 1; i < t.size(); ++i)
            c.line(clamp_int(pixel_of(t[i - 1].first) - cx), clamp_int(pixel_of(t[i - 1].second) - cy),
                   clamp_int(pixel_of(t[i].first) - cx), clamp_int(pixel_of(t[i].second) - cy), kTrailColor);
    for (const EntityView& e : v.entities) {
        const Box b = screen_box(e, cx, cy);
        if (off_canvas(c, b, int(kVelocityScale * (std::fabs(e.vx) + std::fabs(e.vy))) + 1)) continue;
        c.outline_rect(clamp_int(b.left), clamp_int(b.top), clamp_int(b.w), clamp_int(b.h), role_color(e));
        if (e.on_ground)
            c.fill_rect(clamp_int(b.left), clamp_int(b.top + b.h - kGroundMarkHeight), clamp_int(b.w),
                        kGroundMarkHeight, kGroundMarkColor);
        if (e.vx != 0 || e.vy != 0) {
            const auto [x, y] = centre(e, cx, cy);
            c.line(x, y, clamp_int(x + std::lround(e.vx * kVelocityScale)),
                   clamp_int(y + std::lround(e.vy * kVelocityScale)), kVelocityColor);
        }
    }
    for (const auto& [i, j] : v.pushed_pairs) {
        if (i >= v.entities.size() || j >= v.entities.size()) continue;
        const auto [x0, y0] = centre(v.entities[i], cx, cy);
        const auto [x1, y1] = centre(v.entities[j], cx, cy);
        c.line(x0, y0, x1, y1, kPushedPairColor);
    }
    draw_legend(c);
}

}  // namespace

CellWindow visible_cells(const TileLayer& layer, int tile_w, int tile_h, int64_t view_x,
                         int64_t view_y, int view_w, int view_h, int over_w, int over_h) {
    CellWindow w;
    if (tile_w <= 0 || tile_h <= 0) return w;
    w.col0 = std::max(layer.origin_col, floor_div(view_x - over_w, tile_w));
    w.col1 = std::min(layer.origin_col + layer.width, floor_div(view_x + view_w - 1, tile_w) + 1);
    w.row0 = std::max(layer.origin_row, floor_div(view_y, tile_h));
    w.row1 = std::min(layer.origin_row + layer.height, floor_div(view_y + view_h - 1 + over_h, tile_h) + 1);
    if (w.col1 < w.col0) w.col1 = w.col0;
    if (w.row1 < w.row0) w.row1 = w.row0;
    return w;
}

namespace {

// A layer offset in whole px, floored as the camera is; bounded to the
// range where the core's coordinates are exact, so no cast overflows.
int64_t offset_px(double offset) {
    constexpr double kExact = 9007199254740992.0;  // 2^53
    return int64_t(std::floor(std::clamp(offset, -kExact, kExact)));
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

size_t draw_layer(Canvas& c, TileArt& art, const Tilemap& map, const TileLayer& layer, int64_t cx,
                  int64_t cy, std::pair<int, int> over, double time_ms) {
    const uint8_t alpha = opacity_alpha(layer.opacity);
    // A layer's offset moves it as a camera moving the other way would.
    const int64_t lx = cx - offset_px(layer.offset_x), ly = cy - offset_px(layer.offset_y);
    const CellWindow w = visible_cells(layer, map.tile_width, map.tile_height, lx, ly, c.width(),
                                       c.height(), over.first, over.second);
    size_t drawn = 0;
    for (int64_t row = w.row0; row < w.row1; ++row) {
        const size_t first = static_cast<size_t>((row - layer.origin_row) * layer.width - layer.origin_col);
        for (int64_t col = w.col0; col < w.col1; ++col) {
            const uint32_t gid = layer.cells[first + static_cast<size_t>(col)];
            if (!gid) continue;
            const int64_t x = col * map.tile_width - lx;
            SDL_Surface* pic = art.tile(gid, time_ms);
            if (!pic) {
                if (!map.gid_known(gid)) draw_missing(c, x, row * map.tile_height - ly, map.tile_width, map.tile_height, alpha);
                continue;
            }
            c.blit(pic, int(x), int((row + 1) * map.tile_height - pic->h - ly), alpha);
            ++drawn;
        }
    }
    return drawn;
}

}  // namespace

size_t draw_map(Canvas& c, TileArt& art, const Tilemap& map, int64_t cx, int64_t cy, double time_ms) {
    const std::pair<int, int> over = overhang(map);
    size_t drawn = 0;
    for (const TileLayer& layer : map.layers)
        if (layer.visible && layer.opacity > 0) drawn += draw_layer(c, art, map, layer, cx, cy, over, time_ms);
    return drawn;
}

DrawCounts draw_scene(Canvas& c, TileArt& art, const SceneView& v) {
    DrawCounts n;
    const int64_t cx = pixel_of(v.camera_x), cy = pixel_of(v.camera_y);
    art.bind(v.map);
    c.clear(kBackground);
    if (v.map) n.tiles = draw_map(c, art, *v.map, cx, cy, v.time_ms);
    draw_entities(c, art, v, cx, cy, n);
    if (v.commands)
        for (const DrawCommand& d : v.commands->commands) draw_command(c, art, d, cx, cy, v.time_ms);
    if (v.commands) n.commands = v.commands->commands.size();
    if (v.debug) draw_overlay(c, v, cx, cy);
    return n;
}

}  // namespace ds::render
