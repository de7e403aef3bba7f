// SPDX-License-Identifier: MIT
// Draws a Tiled map as Tiled draws an orthogonal map: every layer in the
// file's order (tile layers, the tile objects of object layers, image
// layers; groups passing on their visibility, opacity, tint, offset and
// parallax), under a camera.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "canvas.hpp"
#include "tile_art.hpp"
#include "tilemap/tilemap.hpp"

namespace ds::render {

// A layer that draws (tile, object or image), with what its groups pass on:
// visible and opacity multiplied, offsets summed, parallax factors and tint
// multiplied.
struct DrawnLayer {
    LayerKind kind = LayerKind::Tile;
    size_t index = 0;  // Tile: into Tilemap::layers; Object: into object_layers
    const LayerInfo* info = nullptr;  // nullptr for a map without a layer tree
    bool visible = true;
    double opacity = 1;
    double offset_x = 0, offset_y = 0;
    double parallax_x = 1, parallax_y = 1;
    Rgba tint{255, 255, 255, 255};
};

// The map's drawing layers in the file's order (groups flattened); a map
// made in memory, without a layer tree, draws its tile layers.
std::vector<DrawnLayer> drawn_layers(const Tilemap& map);

// Where a layer's (0, 0) lands on the canvas, as a camera: the camera's
// top-left corner (cam_x, cam_y), moved by the layer's offset and its
// parallax, (1 − factor) × (view centre − the map's parallax origin), as
// Tiled's manual gives it. Floored to whole px as the camera is.
struct LayerCamera {
    int64_t x = 0, y = 0;
};
LayerCamera layer_camera(const Tilemap& map, const DrawnLayer& layer, int64_t cam_x, int64_t cam_y,
                         int view_w, int view_h);

// Draws layers [first, last) of `layers` (drawn_layers of `map`); returns
// how many tiles (cells and tile objects) and images it drew.
size_t draw_layers(Canvas& canvas, TileArt& art, const Tilemap& map, std::span<const DrawnLayer> layers,
                   int64_t cam_x, int64_t cam_y, double time_ms);

// Every layer of the map (draw_scene's map, without the entities).
size_t draw_map(Canvas& canvas, TileArt& art, const Tilemap& map, int64_t cam_x, int64_t cam_y,
                double time_ms = 0);

}  // namespace ds::render
