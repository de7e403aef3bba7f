// SPDX-License-Identifier: MIT
// Draws a SceneView into a canvas: the map's visible tile layers in order,
// the entities, the render hook's commands, then the debug overlay.
#pragma once
#include "canvas.hpp"
#include "map_draw.hpp"
#include "scene_view.hpp"
#include "tile_art.hpp"

namespace ds::render {

// What drawing one frame did, for engine-stats.
struct DrawCounts {
    size_t tiles = 0, sprites = 0, boxes = 0, commands = 0;
};

// Clears to the view's background, else the map's (backgroundcolor=, drawn
// opaque), else kBackground; draws the map's layers with the entities after
// the object layer view.entity_layer names (after every layer when it names
// none), then the render hook's commands and the debug overlay.
DrawCounts draw_scene(Canvas& canvas, TileArt& art, const SceneView& view);

// How many of `layers` are drawn before the entities: up to and including
// the first object layer called `name`; all of them when none is.
size_t entity_split(std::span<const DrawnLayer> layers, std::string_view name);

}  // namespace ds::render
