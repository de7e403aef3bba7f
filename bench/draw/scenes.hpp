// SPDX-License-Identifier: MIT
// What `downstroke-bench draw` draws: square maps made in memory from the
// demo tiles, sprites spread over a map or packed into the view, and the
// camera's path. All deterministic, so every run draws the same frames.
#pragma once
#include <vector>

#include "scene_view.hpp"
#include "tilemap/tilemap.hpp"

namespace bench::draw {

constexpr int kTile = 16;                    // px, the demo tiles' size
constexpr int kViewW = 640, kViewH = 360;    // the canvas: a 16:9 pixel-art game
constexpr int kSprites = 10000;
constexpr int kMapSide = 1000;               // cells, the main scene's map
constexpr int kSizes[] = {100, kMapSide, 4000};  // cells, the map-size cases

// side × side cells, two layers: "ground" full, "detail" on about a quarter
// of the cells; about a quarter of the gids carry flip bits. A cell's gids
// depend on its column and row only, so every map shows the same tiles
// wherever their views overlap.
ds::Tilemap make_map(int side);

// The Tiled-layers case (issue 34): make_map(side) with, in file order, an
// image layer (the demo backdrop, 192 × 240 px) repeated along both axes at
// parallax 0.2, the ground layer, the detail layer at parallax 0.5, and an
// object layer of kTileObjects tile objects spread over the first
// kObjectArea × kObjectArea px (flipped, a fifth stretched, a tenth turned),
// plus `out_of_view` more beyond it, where the camera never looks; the
// object layer indexed as the loader indexes it.
constexpr int kTileObjects = 2000;
constexpr int kObjectArea = 100 * kTile;  // the first 100² cells: what the small-area cases cross
ds::Tilemap make_tiled_map(int side, int out_of_view);

// Sprites (16×16, gids 1–4, a third flipped) with velocities and roles that
// the debug overlay shows, at random points of [0, w) × [0, h) px.
std::vector<ds::render::EntityView> spread_sprites(int count, double w, double h);

// Where the camera is at frame i of n: on the diagonal from the top-left to
// the bottom-right of an area of w × h px, so the view crosses it once per n
// frames, at fractional positions.
struct Camera {
    double x = 0, y = 0;
};
Camera camera_at(int i, int n, double w, double h);

// Sprites spread over the view instead, a pixel in from each edge so that
// flooring the camera never pushes one out: the worst case, all on screen.
std::vector<ds::render::EntityView> view_sprites(int count);
// Puts sprite i at the camera plus view-space sprite i.
void pin_to_view(std::vector<ds::render::EntityView>& sprites,
                 const std::vector<ds::render::EntityView>& offsets, Camera cam);

}  // namespace bench::draw
