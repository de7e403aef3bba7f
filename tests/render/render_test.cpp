// SPDX-License-Identifier: MIT
// Drawing, checked pixel by pixel against expectations computed here from
// the picture's definition (not from the renderer's code): tiles at known
// cells, every flip bit, the camera, sprites, boxes, the overlay, the draw
// list, opacity, image collections, culling and PNG capture.
#include <doctest/doctest.h>

#include <SDL_image.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "canvas.hpp"
#include "child_process.hpp"
#include "constants.hpp"
#include "font.hpp"
#include "render_error.hpp"
#include "scene_draw.hpp"
#include "test_sheet.hpp"
#include "window.hpp"

using namespace ds;
using namespace ds::render;
using namespace ds::render::test;

namespace {

// Where Tiled puts source pixel (x, y) of a tile under `flips`: the diagonal
// flip swaps the axes first, then the horizontal and vertical flips mirror.
std::pair<int, int> forward(int x, int y, uint32_t flips) {
    if (flips & kFlipDiagonal) std::swap(x, y);
    if (flips & kFlipHorizontal) x = kTile - 1 - x;
    if (flips & kFlipVertical) y = kTile - 1 - y;
    return {x, y};
}

void check_tile_at(const Canvas& c, int left, int top, int t, uint32_t flips) {
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) {
            const auto [dx, dy] = forward(x, y, flips);
            CAPTURE(t);
            CAPTURE(flips);
            CAPTURE(x);
            CAPTURE(y);
            CHECK(c.pixel(left + dx, top + dy) == sheet_color(t, x, y));
        }
}

Rgba blended(Rgba src, Rgba dst, uint8_t a) {  // the usual "over", rounded
    auto m = [a](int s, int d) { return uint8_t((s * a + d * (255 - a) + 127) / 255); };
    return {m(src.r, dst.r), m(src.g, dst.g), m(src.b, dst.b), 255};
}

// Draws the entities `es` over the map `m` (none: nullptr) onto `c`, as a
// frame's scene is drawn, with no camera, overlay or draw commands.
DrawCounts draw_entities(Canvas& c, const Tilemap* m, std::span<const EntityView> es) {
    TileArt art;
    SceneView v;
    v.map = m;
    v.entities = es;
    return draw_scene(c, art, v);
}

}  // namespace

TEST_SUITE("render") {

TEST_CASE("each tile is drawn from its place in the sheet at its cell") {
    Tilemap m = map_with(3, 2, {1, 2, 0, 3, 4, 1});
    Canvas c(12, 8);
    TileArt art;
    art.bind(&m);
    c.clear(kBackground);
    CHECK(draw_map(c, art, m, 0, 0) == 5);
    check_tile_at(c, 0, 0, 0, 0);
    check_tile_at(c, 4, 0, 1, 0);
    check_tile_at(c, 0, 4, 2, 0);
    check_tile_at(c, 4, 4, 3, 0);
    check_tile_at(c, 8, 4, 0, 0);
    CHECK(c.pixel(9, 1) == kBackground);  // the empty cell
    CHECK(art.images_loaded() == 1);
}

TEST_CASE("every combination of the flip bits turns the tile as Tiled does") {
    const uint32_t combos[] = {kFlipHorizontal, kFlipVertical, kFlipDiagonal,
                               kFlipHorizontal | kFlipVertical, kFlipDiagonal | kFlipHorizontal,
                               kFlipDiagonal | kFlipVertical, kFlipDiagonal | kFlipHorizontal | kFlipVertical};
    for (uint32_t flips : combos) {
        Tilemap m = map_with(1, 1, {2 | flips});
        Canvas c(4, 4);
        TileArt art;
        art.bind(&m);
        draw_map(c, art, m, 0, 0);
        check_tile_at(c, 0, 0, 1, flips);
    }
    // The hexagonal rotation bit means nothing on an orthogonal map.
    Tilemap m = map_with(1, 1, {2 | kRotateHex120});
    Canvas c(4, 4);
    TileArt art;
    art.bind(&m);
    draw_map(c, art, m, 0, 0);
    check_tile_at(c, 0, 0, 1, 0);
}

TEST_CASE("the camera shifts the map by its floored position") {
    Tilemap m = map_with(4, 4, std::vector<uint32_t>(16, 1));
    m.layers[0].cells[5] = 4;  // cell (1, 1): world pixels 4–7
    Canvas c(8, 8);
    TileArt art;
    SceneView v;
    v.map = &m;
    v.camera_x = 3.75;  // floors to 3
    v.camera_y = 2;
    draw_scene(c, art, v);
    check_tile_at(c, 4 - 3, 4 - 2, 3, 0);
    CHECK(c.pixel(0, 0) == sheet_color(0, 3, 2));
}

TEST_CASE("a tile past the end of its tileset's image is drawn as a missing tile, in cells and as an object") {
    Tilemap m = map_with(3, 1, {4, 5, 6});  // the sheet's image holds local ids 0-3
    m.tilesets[0].tile_count = 6;           // so gids 5 and 6 are the tileset's, with no picture
    m.object_layers.push_back({});
    MapObject o;
    o.shape = ObjectShape::Tile;
    o.gid = 6, o.x = 8, o.y = 8, o.width = kTile, o.height = kTile;
    m.object_layers[0].objects.push_back(o);
    m.layer_tree.resize(2);
    m.layer_tree[0].kind = LayerKind::Tile;
    m.layer_tree[1].kind = LayerKind::Object;
    Canvas c(12, 8);
    TileArt art;
    art.bind(&m);
    c.clear(kBackground);
    CHECK(draw_map(c, art, m, 0, 0) == 1);  // only gid 4 has a picture
    check_tile_at(c, 0, 0, 3, 0);
    const Rgba magenta{255, 0, 255, 255};
    for (int left : {4, 8})
        for (int y = 0; y < kTile; ++y)
            for (int x = 0; x < kTile; ++x) {
                const bool edge = x == 0 || y == 0 || x == kTile - 1 || y == kTile - 1;
                CAPTURE(left);
                CAPTURE(x);
                CAPTURE(y);
                CHECK(c.pixel(left + x, y) == (edge ? magenta : blended(magenta, kBackground, 96)));
            }
    for (int y = kTile; y < 8; ++y)
        for (int x = 0; x < 12; ++x) {
            const bool object = x >= 8 && (x == 8 || y == kTile || x == 11 || y == 7);
            CAPTURE(x);
            CAPTURE(y);
            CHECK(c.pixel(x, y) == (object ? magenta : x >= 8 ? blended(magenta, kBackground, 96) : kBackground));
        }
}

TEST_CASE("a gid no tileset holds is drawn as a missing tile: a faint magenta cell, outlined") {
    Tilemap m = map_with(2, 1, {1, 9});  // the sheet holds gids 1-4
    Canvas c(8, 4);
    TileArt art;
    art.bind(&m);
    c.clear(kBackground);
    CHECK(draw_map(c, art, m, 0, 0) == 1);  // the missing cell is marked, not counted as drawn
    check_tile_at(c, 0, 0, 0, 0);
    const Rgba magenta{255, 0, 255, 255};
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) {
            const bool edge = x == 0 || y == 0 || x == kTile - 1 || y == kTile - 1;
            CAPTURE(x);
            CAPTURE(y);
            CHECK(c.pixel(4 + x, y) == (edge ? magenta : blended(magenta, kBackground, 96)));
        }
}

TEST_CASE("a layer's offset moves its tiles by whole pixels, rounded as Tiled rounds: halves up") {
    Tilemap m = map_with(1, 1, {2});
    m.layers[0].offset_x = 2.5;   // rounds to 3
    m.layers[0].offset_y = -1.5;  // rounds to -1, not -2
    Canvas c(8, 8);
    TileArt art;
    art.bind(&m);
    c.clear(kBackground);
    CHECK(draw_map(c, art, m, 0, 0) == 1);
    // Row 0 of the tile is above the canvas; rows 1-3 land on 0-2.
    for (int y = 1; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) CHECK(c.pixel(3 + x, y - 1) == sheet_color(1, x, y));
    CHECK(c.pixel(2, 0) == kBackground);
    CHECK(c.pixel(3, 3) == kBackground);
    m.layers[0].offset_x = 2.4999, m.layers[0].offset_y = -0.5;  // 2 and 0
    c.clear(kBackground);
    CHECK(draw_map(c, art, m, 0, 0) == 1);
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) CHECK(c.pixel(2 + x, y) == sheet_color(1, x, y));
    CHECK(c.pixel(1, 0) == kBackground);
}

TEST_CASE("an animated tile shows the frame the game's clock is in, and starts over") {
    Tilemap m = map_with(2, 1, {1, 2 | kFlipHorizontal});
    TileInfo anim;  // local tile 0 plays 1 (100 ms), 3 (50 ms); tile 1 plays 2 then 0
    anim.id = 0;
    anim.animation = {{1, 100}, {3, 50}};
    TileInfo flipped;
    flipped.id = 1;
    flipped.animation = {{2, 10}, {0, 0}, {0, 10}};  // a zero-length frame never shows
    m.tilesets[0].tiles = {anim, flipped};
    const struct {
        double ms;
        int first, second;
    } moments[] = {{0, 1, 2}, {99, 1, 0}, {100, 3, 2}, {149, 3, 2}, {150, 1, 0}, {1234, 1, 0}};
    for (const auto& at : moments) {
        Canvas c(8, 4);
        TileArt art;
        art.bind(&m);
        CAPTURE(at.ms);
        CHECK(draw_map(c, art, m, 0, 0, at.ms) == 2);
        check_tile_at(c, 0, 0, at.first, 0);
        check_tile_at(c, 4, 0, at.second, kFlipHorizontal);  // the cell's flips turn every frame
    }
}

TEST_CASE("only the cells in view are visited, however large the layer") {
    TileLayer big;
    big.width = big.height = 100000;  // no cells needed: the window is pure arithmetic
    const CellWindow w = visible_cells(big, 16, 16, 1000, 2000, 640, 360, 0, 0);
    CHECK(w.col0 == 62);
    CHECK(w.col1 == 103);  // 1000 + 640 − 1 = 1639 → cell 102 is the last
    CHECK(w.row0 == 125);
    CHECK(w.row1 == 148);  // 2000 + 360 − 1 = 2359 → cell 147
    // Taller tiles hang above their cell, so rows below the view can show.
    CHECK(visible_cells(big, 16, 16, 1000, 2000, 640, 360, 0, 16).row1 == 149);
    // Before the layer's first cell there is nothing.
    const CellWindow left = visible_cells(big, 16, 16, -5000, 0, 640, 360, 0, 0);
    CHECK(left.col0 == 0);
    CHECK(left.col1 == 0);
}

TEST_CASE("a sprite stands bottom-centred in its entity's box, flip-x mirrors it") {
    Tilemap m = map_with(1, 1, {0});
    std::vector<EntityView> es(2);
    es[0] = {.x = 2, .y = 1, .w = 6, .h = 5, .sprite = 4};  // drawn at (3, 2)
    es[1] = {.x = 10, .y = 0, .w = 4, .h = 4, .sprite = 2, .flip_x = true};
    Canvas c(16, 8);
    const DrawCounts n = draw_entities(c, &m, es);
    CHECK(n.sprites == 2);
    CHECK(n.boxes == 0);
    check_tile_at(c, 3, 2, 3, 0);
    check_tile_at(c, 10, 0, 1, kFlipHorizontal);
}

TEST_CASE("an entity with no sprite draws nothing unless it has a colour; the overlay outlines it by role") {
    std::vector<EntityView> es(6);
    es[0] = {.x = 0, .y = 0, .w = 4, .h = 4, .vx = 1, .solid = true};
    es[1] = {.x = 5, .y = 0, .w = 4, .h = 4, .solid = true, .immovable = true};
    es[2] = {.x = 10, .y = 0, .w = 4, .h = 4, .solid = true, .ghost = true};
    es[3] = {.x = 15, .y = 0, .w = 4, .h = 4};
    es[4] = {.x = 20, .y = 0, .w = 4, .h = 4, .solid = true, .on_ground = true};
    es[5] = {.x = 25, .y = 0, .w = 4, .h = 4, .solid = true, .immovable = true, .sensor = true};
    Canvas c(30, 20);  // the overlay's legend is along the bottom, below them
    TileArt art;
    SceneView v;
    v.entities = es;
    const DrawCounts n = draw_scene(c, art, v);
    CHECK(n.boxes == 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 30; ++x) CHECK(c.pixel(x, y) == kBackground);
    v.debug = true;
    draw_scene(c, art, v);
    const Rgba roles[] = {kSolidColor, kImmovableColor, kGhostColor, kPlainColor, kRestingColor, kSensorColor};
    for (int i = 0; i < 6; ++i) {
        CAPTURE(i);
        CHECK(c.pixel(i * 5, 0) == roles[i]);  // the outline
        CHECK(c.pixel(i * 5 + 3, 1) == roles[i]);  // its right edge, above the ground mark
        CHECK(c.pixel(i * 5 + 1, 1) == kBackground);  // an outline only
    }
}

TEST_CASE("an entity's colour fills its box, blended by its alpha; a sprite no map holds falls back to it") {
    std::vector<EntityView> es(3);
    es[0] = {.x = 1, .y = 1, .w = 3, .h = 2, .color = Rgba{200, 40, 60, 255}};
    es[1] = {.x = 6, .y = 0, .w = 2, .h = 2, .color = Rgba{0, 100, 200, 128}};
    es[2] = {.x = 9, .y = 0, .w = 1, .h = 1, .sprite = 3, .color = Rgba{1, 2, 3, 255}};  // no map: no picture
    Canvas c(12, 4);
    CHECK(draw_entities(c, nullptr, es).boxes == 3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) CHECK(c.pixel(x, y) == (x >= 1 && x < 4 && y >= 1 && y < 3 ? Rgba{200, 40, 60, 255} : kBackground));
    CHECK(c.pixel(7, 1) == blended({0, 100, 200, 255}, kBackground, 128));
    CHECK(c.pixel(9, 0) == Rgba{1, 2, 3, 255});
}

TEST_CASE("a hidden entity draws nothing, sprite or colour") {
    Tilemap m = map_with(1, 1, {0});
    std::vector<EntityView> es(2);
    es[0] = {.x = 0, .y = 0, .w = 4, .h = 4, .sprite = 2, .visible = false};
    es[1] = {.x = 4, .y = 0, .w = 4, .h = 4, .visible = false, .color = Rgba{255, 0, 0, 255}};
    Canvas c(8, 4);
    const DrawCounts n = draw_entities(c, &m, es);
    CHECK(n.sprites + n.boxes == 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) CHECK(c.pixel(x, y) == kBackground);
}

TEST_CASE("a sprite's offset moves it by exactly (dx, dy); its body stays") {
    Tilemap m = map_with(1, 1, {0});
    std::vector<EntityView> es(1);
    es[0] = {.x = 2, .y = 1, .w = 6, .h = 5, .sprite = 4, .sprite_dx = 5, .sprite_dy = -1};  // unmoved at (3, 2)
    Canvas c(16, 8);
    CHECK(draw_entities(c, &m, es).sprites == 1);
    check_tile_at(c, 8, 1, 3, 0);
    CHECK(c.pixel(3, 5) == kBackground);  // where it stood unmoved (below the moved one's rows)
    CHECK(c.pixel(7, 2) == kBackground);
}

TEST_CASE("a moved, scaled or turned sprite is culled where its picture is, not its body") {
    Tilemap m = map_with(1, 1, {0});
    std::vector<EntityView> es(3);
    es[0] = {.x = -40, .y = 0, .w = 4, .h = 4, .sprite = 4, .scale_x = 64, .scale_y = 64, .degrees = 45};  // huge, reaching in
    es[1] = {.x = 0, .y = 0, .w = 4, .h = 4, .sprite = 3, .sprite_dx = 2000};      // body in view, picture far away
    es[2] = {.x = 1000, .y = 0, .w = 4, .h = 4, .sprite = 2, .sprite_dx = -1000};  // body far away, picture at (0, 0)
    Canvas c(8, 4);
    CHECK(draw_entities(c, &m, es).sprites == 2);
    check_tile_at(c, 0, 0, 1, 0);
}

TEST_CASE("a sprite scaled 2 is twice its size, standing on the same bottom-centre") {
    Tilemap m = map_with(1, 1, {0});
    std::vector<EntityView> es(2);
    // Unscaled, tile 1 would cover (4..7, 8..11): its bottom-centre is (6, 12).
    es[0] = {.x = 4, .y = 8, .w = 4, .h = 4, .sprite = 2, .scale_x = 2, .scale_y = 2};
    // Only x doubled: 8 × 4 on the same bottom-centre (18, 4).
    es[1] = {.x = 16, .y = 0, .w = 4, .h = 4, .sprite = 3, .scale_x = 2};
    Canvas c(28, 16);
    CHECK(draw_entities(c, &m, es).sprites == 2);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            CHECK(c.pixel(2 + x, 4 + y) == sheet_color(1, x / 2, y / 2));
        }
    CHECK(c.pixel(1, 8) == kBackground);
    CHECK(c.pixel(10, 8) == kBackground);
    CHECK(c.pixel(5, 3) == kBackground);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) CHECK(c.pixel(14 + x, y) == sheet_color(2, x / 2, y));
    CHECK(c.pixel(13, 0) == kBackground);
    CHECK(c.pixel(22, 0) == kBackground);
}

TEST_CASE("a sprite turned 90 degrees turns clockwise about its centre") {
    Tilemap m = map_with(1, 1, {0});
    std::vector<EntityView> es(1);
    es[0] = {.x = 4, .y = 4, .w = 4, .h = 4, .sprite = 2, .degrees = 90};  // unturned: (4..7, 4..7), centre (6, 6)
    Canvas c(12, 12);
    draw_entities(c, &m, es);
    // Clockwise on screen (y down): the offset (a, b) from the centre goes to
    // (−b, a), so pixel (u, v)'s centre (4.5 + u, 4.5 + v) lands on
    // (7.5 − v, 4.5 + u): pixel (7 − v, 4 + u). The top-left corner goes top-right.
    for (int sv = 0; sv < kTile; ++sv)
        for (int su = 0; su < kTile; ++su) {
            CAPTURE(su);
            CAPTURE(sv);
            CHECK(c.pixel(7 - sv, 4 + su) == sheet_color(1, su, sv));
        }
    CHECK(c.pixel(7, 4) == sheet_color(1, 0, 0));
    CHECK(c.pixel(8, 4) == kBackground);
}

TEST_CASE("each entity's animated sprite plays by its own clock; without one, by the scene's") {
    Tilemap m = map_with(1, 1, {0});
    TileInfo anim;  // local tile 0 plays 1 (100 ms), 3 (50 ms)
    anim.id = 0;
    anim.animation = {{1, 100}, {3, 50}};
    m.tilesets[0].tiles = {anim};
    std::vector<EntityView> es(3);
    es[0] = {.x = 0, .y = 0, .w = 4, .h = 4, .sprite = 1, .sprite_ms = 0.0};
    es[1] = {.x = 4, .y = 0, .w = 4, .h = 4, .sprite = 1, .sprite_ms = 100.0};
    es[2] = {.x = 8, .y = 0, .w = 4, .h = 4, .sprite = 1};
    Canvas c(12, 4);
    TileArt art;
    SceneView v;
    v.map = &m;
    v.entities = es;
    v.time_ms = 120;
    draw_scene(c, art, v);
    check_tile_at(c, 0, 0, 1, 0);
    check_tile_at(c, 4, 0, 3, 0);
    check_tile_at(c, 8, 0, 3, 0);
}

TEST_CASE("the debug overlay: outlines, velocity, ground mark, pushed pairs, trails") {
    std::vector<EntityView> es(2);
    es[0] = {.x = 2, .y = 2, .w = 5, .h = 5, .vx = 0, .vy = 2, .solid = true, .on_ground = true};
    es[1] = {.x = 20, .y = 2, .w = 5, .h = 5, .solid = true};
    const std::pair<uint32_t, uint32_t> pairs[] = {{0, 1}};
    const Trail trails[] = {{{30.5, 20.5}, {34.5, 20.5}}, {}};
    Canvas c(40, 40);
    TileArt art;
    SceneView v;
    v.entities = es;
    v.debug = true;
    v.pushed_pairs = pairs;
    v.trails = trails;
    draw_scene(c, art, v);
    // Entity 0's centre is (4, 4); its velocity (0, 2) is drawn 4 frames long.
    CHECK(c.pixel(4, 4 + 2 * int(kVelocityScale)) == kVelocityColor);
    CHECK(c.pixel(4, 5 + 2 * int(kVelocityScale)) == kBackground);
    // The pushed pair runs centre to centre along y = 4, past the velocity.
    CHECK(c.pixel(15, 4) == kPushedPairColor);
    // The ground mark: the box's bottom rows.
    CHECK(c.pixel(3, 6) == kGroundMarkColor);
    CHECK(c.pixel(3, 6 - kGroundMarkHeight) != kGroundMarkColor);
    // The trail from (30, 20) to (34, 20).
    for (int x = 30; x <= 34; ++x) CHECK(c.pixel(x, 20) == kTrailColor);
    // The legend names the roles along the bottom edge.
    bool legend = false;
    for (int x = 0; x < 40; ++x) legend |= c.pixel(x, 40 - kLineHeight + 3) == kSolidColor;
    CHECK(legend);
}

TEST_CASE("draw commands: world space moves with the camera, screen space does not") {
    DrawList list;
    list.commands.push_back({.kind = DrawCommand::Kind::FilledRect, .space = Space::World, .x = 10, .y = 10,
                             .x2 = 2, .y2 = 2, .color = {255, 0, 0, 255}});
    list.commands.push_back({.kind = DrawCommand::Kind::FilledRect, .space = Space::Screen, .x = 0, .y = 0,
                             .x2 = 1, .y2 = 1, .color = {0, 0, 255, 255}});
    list.commands.push_back({.kind = DrawCommand::Kind::Line, .space = Space::Screen, .x = 0, .y = 7, .x2 = 7,
                             .y2 = 7, .color = {0, 255, 0, 128}});
    list.commands.push_back({.kind = DrawCommand::Kind::Rect, .space = Space::Screen, .x = 12, .y = 0, .x2 = 3,
                             .y2 = 3, .color = {255, 255, 0, 255}});
    Canvas c(16, 16);
    TileArt art;
    SceneView v;
    v.camera_x = 5;
    v.camera_y = 6;
    v.commands = &list;
    draw_scene(c, art, v);
    CHECK(c.pixel(5, 4) == Rgba{255, 0, 0, 255});
    CHECK(c.pixel(6, 5) == Rgba{255, 0, 0, 255});
    CHECK(c.pixel(7, 6) == kBackground);
    CHECK(c.pixel(0, 0) == Rgba{0, 0, 255, 255});
    for (int x = 0; x <= 7; ++x) CHECK(c.pixel(x, 7) == blended({0, 255, 0, 255}, kBackground, 128));
    CHECK(c.pixel(8, 7) == kBackground);
    CHECK(c.pixel(12, 0) == Rgba{255, 255, 0, 255});
    CHECK(c.pixel(13, 1) == kBackground);  // an outline is hollow
    CHECK(c.pixel(14, 2) == Rgba{255, 255, 0, 255});
}

TEST_CASE("text is the built-in font, pixel for pixel, at any scale") {
    Canvas c(20, 20);
    c.clear({0, 0, 0, 255});
    c.text(1, 2, "H", {255, 255, 255, 255}, 2);
    for (int row = 0; row < kGlyphHeight; ++row)
        for (int col = 0; col < kGlyphWidth; ++col) {
            const bool ink = glyph_row('H', row) >> (kGlyphWidth - 1 - col) & 1;
            const Rgba want = ink ? Rgba{255, 255, 255, 255} : Rgba{0, 0, 0, 255};
            CHECK(c.pixel(1 + col * 2, 2 + row * 2) == want);
            CHECK(c.pixel(2 + col * 2, 3 + row * 2) == want);
        }
}

TEST_CASE("lines far off the canvas are clipped, not walked") {
    Canvas c(8, 8);
    c.clear({0, 0, 0, 255});
    c.line(-2000000000, 3, 2000000000, 3, {255, 255, 255, 255});
    for (int x = 0; x < 8; ++x) CHECK(c.pixel(x, 3) == Rgba{255, 255, 255, 255});
    CHECK(c.pixel(0, 2) == Rgba{0, 0, 0, 255});
    c.line(-50, -50, -10, -10, {255, 0, 0, 255});  // wholly outside: nothing
    CHECK(c.pixel(0, 0) == Rgba{0, 0, 0, 255});
}

TEST_CASE("a layer's opacity fades its tiles; a hidden layer is not drawn") {
    Tilemap m = map_with(1, 1, {1});
    m.layers[0].opacity = 0.5;
    TileLayer hidden = m.layers[0];
    hidden.cells = {4};
    hidden.visible = false;
    hidden.opacity = 1;
    m.layers.push_back(hidden);
    Canvas c(4, 4);
    TileArt art;
    art.bind(&m);
    c.clear({0, 0, 0, 255});
    draw_map(c, art, m, 0, 0);
    const Rgba want = blended(sheet_color(0, 1, 2), {0, 0, 0, 255}, 128);
    const Rgba got = c.pixel(1, 2);
    // SDL's blitter may round a unit differently from ours.
    CHECK(std::abs(got.r - want.r) <= 1);
    CHECK(std::abs(got.g - want.g) <= 1);
    CHECK(std::abs(got.b - want.b) <= 1);
}

TEST_CASE("an image-collection tileset draws each tile from its own file") {
    write_sheet("one.png");  // an 8 × 8 picture: tile 7 is the whole sheet
    Tilemap m;
    m.width = m.height = 2;
    m.tile_width = m.tile_height = kTile;
    Tileset ts;
    ts.firstgid = 1;
    ts.tile_width = ts.tile_height = 8;
    ts.image_dir = temp_dir().string();
    TileInfo t;
    t.id = 7;
    t.image = "one.png";
    t.image_width = t.image_height = 8;
    ts.tiles.push_back(t);
    m.tilesets.push_back(ts);
    TileLayer layer;
    layer.width = layer.height = 2;
    layer.cells = {0, 0, 8, 0};  // gid 8 = local 7 in cell (0, 1)
    m.layers.push_back(layer);
    Canvas c(8, 8);
    TileArt art;
    art.bind(&m);
    draw_map(c, art, m, 0, 0);
    // Bottom-left aligned: the 8 px picture in a 4 px cell at row 1 fills y 0–7.
    check_tile_at(c, 0, 0, 0, 0);
    check_tile_at(c, 4, 4, 3, 0);
}

TEST_CASE("a missing tileset image is reported by file name when first drawn") {
    Tilemap m = map_with(1, 1, {1});
    m.tilesets[0].image = "absent.png";
    Canvas c(4, 4);
    TileArt art;
    art.bind(&m);
    REQUIRE_THROWS_AS(draw_map(c, art, m, 0, 0), RenderError);
    try {
        draw_map(c, art, m, 0, 0);
    } catch (const RenderError& e) {
        CHECK(std::string(e.what()).find("absent.png") != std::string::npos);
    }
    // A gid beyond the tileset's image is drawn as nothing, not an error.
    Tilemap beyond = map_with(1, 1, {9});
    art.bind(&beyond);
    CHECK(draw_map(c, art, beyond, 0, 0) == 0);
}

TEST_CASE("a capture is the canvas exactly, unscaled") {
    Tilemap m = map_with(2, 1, {1, 4});
    Canvas c(8, 4);
    TileArt art;
    SceneView v;
    v.map = &m;
    draw_scene(c, art, v);
    const std::string file = (temp_dir() / "capture.png").string();
    c.save_png(file);
    SDL_Surface* back = IMG_Load(file.c_str());
    REQUIRE(back);
    SDL_Surface* argb = SDL_ConvertSurfaceFormat(back, SDL_PIXELFORMAT_ARGB8888, 0);
    CHECK(argb->w == 8);
    CHECK(argb->h == 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const uint32_t p = static_cast<uint32_t*>(argb->pixels)[y * argb->pitch / 4 + x];
            CHECK(Rgba{uint8_t(p >> 16), uint8_t(p >> 8), uint8_t(p), 255} == c.pixel(x, y));
        }
    SDL_FreeSurface(argb);
    SDL_FreeSurface(back);
    CHECK_THROWS_AS(c.save_png("/nonexistent-dir/x.png"), RenderError);
}

namespace {

std::string save_error(const Canvas& c, const std::string& path) {
    try {
        c.save_png(path);
    } catch (const RenderError& e) {
        return e.what();
    }
    return "saved";
}

}  // namespace

TEST_CASE("a capture goes only to a regular file, and a failed write is an error naming it") {
    Canvas c(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) c.fill_rect(x, y, 1, 1, Rgba{uint8_t(x * 4), uint8_t(y * 4), uint8_t(x ^ y), 255});
    const std::string fifo = (temp_dir() / "capture.fifo").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    // No reader: SDL's own writer waited for one for ever.
    CHECK(in_child([&] { return save_error(c, fifo); }) == "cannot write '" + fifo + "': not a regular file");
    std::filesystem::remove(fifo);
    CHECK(save_error(c, "/dev/full") == "cannot write '/dev/full': not a regular file");
    CHECK(save_error(c, temp_dir().string()) == "cannot write '" + temp_dir().string() + "': not a regular file");
    // A full disk, as a file size limit makes one: every write is checked,
    // and the partial picture is not left behind as a frame.
    const std::string big = (temp_dir() / "too-big.png").string();
    const auto save_on_full_disk = [&] {
        return in_child([&] {
            signal(SIGXFSZ, SIG_IGN);
            const rlimit small{100, 100};
            setrlimit(RLIMIT_FSIZE, &small);
            return save_error(c, big);
        });
    };
    CHECK(save_on_full_disk() == "cannot write '" + big + "': File too large");
    CHECK_FALSE(std::filesystem::exists(big));
    // Within the limit, the same picture is written whole.
    CHECK(save_error(c, big) == "saved");
    const auto whole = std::filesystem::file_size(big);
    CHECK(whole > 100);
    // A failed capture over it leaves it as it was, and nothing beside it.
    CHECK(save_on_full_disk() == "cannot write '" + big + "': File too large");
    CHECK(std::filesystem::file_size(big) == whole);
    for (const auto& entry : std::filesystem::directory_iterator(temp_dir()))
        CHECK_FALSE(entry.path().filename().string().starts_with("too-big.png.part-"));
    std::filesystem::remove(big);
}

TEST_CASE("canvas sizes and the window's whole scale") {
    CHECK_THROWS_AS(Canvas(0, 10), RenderError);
    CHECK_THROWS_AS(Canvas(10, kMaxCanvasSide + 1), RenderError);
    CHECK(fitting_scale(320, 240, 1920, 1080) == 4);
    CHECK(fitting_scale(320, 240, 1000, 1000) == 3);
    CHECK(fitting_scale(640, 480, 320, 200) == 1);  // never below 1
    CHECK(fitting_scale(16, 16, 10000, 10000) == kMaxScale);
}

}  // TEST_SUITE
