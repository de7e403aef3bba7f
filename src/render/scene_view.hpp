// SPDX-License-Identifier: MIT
// One frame to draw, as plain data: the map, the camera, the entities' boxes
// and sprites, what the game's render hook asked for, and the debug overlay's
// facts. The bindings fill it from the scene; draw_scene draws it.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include <span>
#include <utility>
#include <vector>

#include "draw_list.hpp"
#include "tilemap/tilemap.hpp"

namespace ds::render {

struct EntityView {
    double x = 0, y = 0, w = 0, h = 0;
    double vx = 0, vy = 0;
    uint32_t sprite = 0;  // a raw gid of the map's tilesets; 0: none (a box only with `color`)
    bool flip_x = false;
    bool solid = false, immovable = false, ghost = false, on_ground = false;
    bool sensor = false;
    // How the entity looks, never where its body is (#:visible?, #:color,
    // #:sprite-offset, #:sprite-scale, #:rotation).
    bool visible = true;
    std::optional<Rgba> color = {};  // without a sprite: a box filled with it
    double sprite_dx = 0, sprite_dy = 0;
    double scale_x = 1, scale_y = 1;  // > 0: flips are flip_x's
    double degrees = 0;               // clockwise, about the sprite's centre
    // The clock its sprite's animated tile plays by (#:animation-start moves
    // it); unset: the scene's, as a map cell's.
    std::optional<double> sprite_ms = {};

    // Whether the sprite is drawn as it stands in its sheet, with no offset,
    // scale or turn: then it is a plain copy, culled by the body's box.
    bool plain_sprite() const {
        return sprite_dx == 0 && sprite_dy == 0 && scale_x == 1 && scale_y == 1 && degrees == 0;
    }
};

// One entity's centres over the remembered frames, oldest first.
using Trail = std::vector<std::pair<double, double>>;

struct SceneView {
    const Tilemap* map = nullptr;
    double camera_x = 0, camera_y = 0;
    std::span<const EntityView> entities;
    const DrawList* commands = nullptr;
    bool debug = false;
    // Indices into entities of the pairs pushed apart in the last frame.
    std::span<const std::pair<uint32_t, uint32_t>> pushed_pairs;
    std::span<const Trail> trails;
    // The object layer the entities are drawn in (after its tile objects, so
    // the layers above it draw over them); empty: after every layer.
    std::string_view entity_layer;
    // The clear colour the game chose; unset: the map's, else the engine's.
    std::optional<Rgba> background;
    // The game's clock in ms (frame number × frame delay): which frame of
    // each animated tile shows.
    double time_ms = 0;
};

// The cells of a layer that can show in a view: columns [col0, col1) and
// rows [row0, row1), in map cells. Tiles taller or wider than the map's
// cells are drawn bottom-left aligned (as Tiled does), so the range reaches
// `over_w` px further left and `over_h` px further down than the view.
struct CellWindow {
    int64_t col0 = 0, col1 = 0, row0 = 0, row1 = 0;
};
CellWindow visible_cells(const TileLayer& layer, int tile_w, int tile_h, int64_t view_x,
                         int64_t view_y, int view_w, int view_h, int over_w, int over_h);

// The camera's pixel: positions are floored once, so a tile and an entity
// standing on it move together by whole pixels. Inline and without libm:
// a frame asks it four times for every entity in the scene, in view or not.
inline int64_t pixel_of(double world) {
    if (!(world > -4.0e15 && world < 4.0e15)) return world >= 4.0e15 ? int64_t(4e15) : world <= -4.0e15 ? -int64_t(4e15) : 0;
    const auto t = static_cast<int64_t>(world);  // toward zero, exact here
    return t > world ? t - 1 : t;
}

}  // namespace ds::render
