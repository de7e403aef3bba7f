// SPDX-License-Identifier: MIT
#include "scene_draw.hpp"

#include <algorithm>
#include <cmath>

#include "constants.hpp"
#include "font.hpp"

namespace ds::render {

namespace {

// The debug overlay's colour for an entity's role.
Rgba role_color(const EntityView& e) {
    if (e.sensor) return kSensorColor;
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

// A box more than this far off the canvas cannot show: skipped before any
// work, so entities far from the view cost one comparison.
bool off_canvas(const Canvas& c, const Box& b, int margin) {
    return b.left + b.w + margin < 0 || b.top + b.h + margin < 0 || b.left - margin > c.width() ||
           b.top - margin > c.height();
}

// Where an entity's sprite goes: standing bottom-centred on its box (whole
// px, as ever), then scaled about its bottom edge's middle (the feet stay
// on the ground), moved by its offset and turned about its own centre.
PictureBox sprite_box(const EntityView& e, const Box& b, SDL_Surface* pic) {
    const int64_t left = b.left + (b.w - pic->w) / 2, bottom = b.top + b.h;
    PictureBox p;
    p.w = pic->w * e.scale_x, p.h = pic->h * e.scale_y;
    p.cx = double(left) + pic->w / 2.0 + e.sprite_dx;
    p.cy = double(bottom) - p.h / 2 + e.sprite_dy;
    p.degrees = e.degrees, p.pivot_x = p.cx, p.pivot_y = p.cy;
    return p;
}

// Whether a turned or scaled picture's box, turned any way about its
// centre, misses the canvas.
bool off_canvas(const Canvas& c, const PictureBox& p) {
    const double r = std::hypot(p.w, p.h) / 2 + 1;
    return !(p.cx + r >= 0 && p.cy + r >= 0 && p.cx - r <= c.width() && p.cy - r <= c.height());
}

void draw_sprite(Canvas& c, SDL_Surface* pic, const EntityView& e, const Box& b) {
    if (e.plain_sprite()) {
        c.blit(pic, clamp_int(b.left + (b.w - pic->w) / 2), clamp_int(b.top + b.h - pic->h));
        return;
    }
    const PictureBox p = sprite_box(e, b, pic);
    const double left = p.cx - p.w / 2, top = p.cy - p.h / 2;
    if (p.degrees == 0 && p.w == pic->w && p.h == pic->h && left == std::floor(left) && top == std::floor(top) &&
        std::fabs(left) < 1e9 && std::fabs(top) < 1e9)
        c.blit(pic, int(left), int(top));  // moved by whole px: a copy, as an unmoved one
    else
        c.draw_picture(pic, p);
}

// An entity is its sprite, else (no sprite, or one no tileset holds) a box
// filled with its #:color, else nothing: the overlay shows every body.
void draw_entities(Canvas& c, TileArt& art, const SceneView& v, int64_t cx, int64_t cy,
                   DrawCounts& n) {
    for (const EntityView& e : v.entities) {
        if (!e.visible || (!e.sprite && !e.color)) continue;
        const Box b = screen_box(e, cx, cy);
        const bool plain = e.plain_sprite();
        if ((plain || !e.sprite) && off_canvas(c, b, 256)) continue;
        SDL_Surface* pic =
            e.sprite ? art.tile(e.sprite ^ (e.flip_x ? kFlipHorizontal : 0), e.sprite_ms.value_or(v.time_ms)) : nullptr;
        if (pic) {
            if (!plain && off_canvas(c, sprite_box(e, b, pic))) continue;
            draw_sprite(c, pic, e, b);
            ++n.sprites;
        } else if (e.color) {
            c.fill_rect(clamp_int(b.left), clamp_int(b.top), clamp_int(b.w), clamp_int(b.h), *e.color);
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
                                                  {"resting", kRestingColor}, {"sensor", kSensorColor}};
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

Rgba map_rgba(const MapColor& m) { return {m.r, m.g, m.b, 255}; }

}  // namespace

size_t entity_split(std::span<const DrawnLayer> layers, std::string_view name) {
    if (!name.empty())
        for (size_t i = 0; i < layers.size(); ++i)
            if (layers[i].kind == LayerKind::Object && layers[i].info && layers[i].info->name == name) return i + 1;
    return layers.size();
}

DrawCounts draw_scene(Canvas& c, TileArt& art, const SceneView& v) {
    DrawCounts n;
    const int64_t cx = pixel_of(v.camera_x), cy = pixel_of(v.camera_y);
    art.bind(v.map);
    c.clear(v.background ? *v.background : v.map && v.map->background ? map_rgba(*v.map->background) : kBackground);
    std::vector<DrawnLayer> layers;
    if (v.map) layers = drawn_layers(*v.map);
    // Entities go after the layer named to hold them, else after the last.
    const size_t split = v.map ? entity_split(layers, v.entity_layer) : 0;
    const std::span<const DrawnLayer> all(layers);
    if (v.map) n.tiles = draw_layers(c, art, *v.map, all.first(split), cx, cy, v.time_ms);
    draw_entities(c, art, v, cx, cy, n);
    if (v.map) n.tiles += draw_layers(c, art, *v.map, all.subspan(split), cx, cy, v.time_ms);
    if (v.commands)
        for (const DrawCommand& d : v.commands->commands) draw_command(c, art, d, cx, cy, v.time_ms);
    if (v.commands) n.commands = v.commands->commands.size();
    if (v.debug) draw_overlay(c, v, cx, cy);
    return n;
}

}  // namespace ds::render
