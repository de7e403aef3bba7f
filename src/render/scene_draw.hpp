// Draws a SceneView into a canvas: the map's visible tile layers in order,
// the entities, the render hook's commands, then the debug overlay.
#pragma once
#include "canvas.hpp"
#include "scene_view.hpp"
#include "tile_art.hpp"

namespace ds::render {

// What drawing one frame did, for engine-stats.
struct DrawCounts {
    size_t tiles = 0, sprites = 0, boxes = 0, commands = 0;
};

DrawCounts draw_scene(Canvas& canvas, TileArt& art, const SceneView& view);

// The map's tile layers alone (part of draw_scene; exposed for tests and the bench).
// time_ms is the game's clock, for animated tiles (SceneView::time_ms).
size_t draw_map(Canvas& canvas, TileArt& art, const Tilemap& map, int64_t cam_x, int64_t cam_y,
                double time_ms = 0);

}  // namespace ds::render
