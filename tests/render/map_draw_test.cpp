// SPDX-License-Identifier: MIT
// Drawing what a Tiled map holds beyond tile layers (issue 34), checked
// against positions and colours computed here from Tiled's documented
// formulas, for what tmxrasterizer (Tiled 1.8) cannot show: parallax under a
// moving camera, tint colours, tilerendersize/fillmode; and the engine's own
// choices: entities between layers, the background, bad input.
#include <doctest/doctest.h>

#include <fstream>

#include "constants.hpp"
#include "render_error.hpp"
#include "scene_draw.hpp"
#include "tilemap/object_index.hpp"
#include "test_sheet.hpp"

using namespace ds;
using namespace ds::render;
using namespace ds::render::test;

namespace {

// A map of `map_with`'s tiles whose layer tree lists its one tile layer.
Tilemap tree_map(int cols, int rows, std::vector<uint32_t> cells, LayerInfo info = {}) {
    Tilemap m = map_with(cols, rows, std::move(cells));
    info.kind = LayerKind::Tile;
    info.index = 0;
    m.layer_tree.push_back(info);
    return m;
}

uint8_t mul(int a, int b) { return uint8_t((a * b + 127) / 255); }

Rgba over(Rgba src, uint8_t a, Rgba dst) {
    auto m = [a](int s, int d) { return uint8_t((s * a + d * (255 - a) + 127) / 255); };
    return {m(src.r, dst.r), m(src.g, dst.g), m(src.b, dst.b), 255};
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_SUITE("map-draw") {

TEST_CASE("a layer's tint multiplies each channel, alpha too, and a group's tint multiplies its children's") {
    LayerInfo group;
    group.kind = LayerKind::Group;
    group.tint = MapColor{200, 100, 255, 255};
    LayerInfo layer;
    layer.tint = MapColor{128, 255, 64, 192};
    Tilemap m = tree_map(1, 1, {1});
    m.layer_tree.clear();
    layer.kind = LayerKind::Tile;
    group.children.push_back(layer);
    m.layer_tree.push_back(group);
    Canvas c(kTile, kTile);
    TileArt art;
    art.bind(&m);
    c.clear(kBackground);
    draw_map(c, art, m, 0, 0);
    // Tiled's tint: colour × tint / 255 per channel; the group's and the
    // layer's multiply first.
    const Rgba t{mul(200, 128), mul(100, 255), mul(255, 64), mul(255, 192)};
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) {
            const Rgba s = sheet_color(0, x, y);
            CHECK(c.pixel(x, y) == over({mul(s.r, t.r), mul(s.g, t.g), mul(s.b, t.b), 255}, t.a, kBackground));
        }
}

TEST_CASE("tilerendersize=grid stretches a tile to the cell; fillmode=preserve-aspect-fit keeps its shape, centred") {
    for (const bool fit : {false, true}) {
        Tilemap m = tree_map(1, 1, {2});
        m.tile_width = 8, m.tile_height = 4;  // cells 8 × 4, tiles 4 × 4
        m.tilesets[0].render_size = TileRenderSize::Grid;
        m.tilesets[0].fill_mode = fit ? FillMode::PreserveAspectFit : FillMode::Stretch;
        Canvas c(8, 4);
        TileArt art;
        art.bind(&m);
        c.clear(kBackground);
        draw_map(c, art, m, 0, 0);
        CAPTURE(fit);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) {
                // Stretch: each source pixel covers 2 × 1 px. Fit: the smaller
                // scale (1) and centred: (8 − 4) / 2 = 2 px in.
                const Rgba want = fit ? (x >= 2 && x < 6 ? sheet_color(1, x - 2, y) : kBackground)
                                      : sheet_color(1, x / 2, y);
                CAPTURE(x);
                CAPTURE(y);
                CHECK(c.pixel(x, y) == want);
            }
    }
}

TEST_CASE("parallax: a layer moves by (1 − factor) × (view centre − parallax origin), through its groups") {
    // One tile at cell (5, 2); a view 40 × 32 px. For each camera, the tile's
    // top-left on the canvas is cell × 4 − ⌊camera − shift⌋ (the layer's own
    // camera, floored to whole px as the camera is), with shift = (1 − f) ×
    // (camera + view / 2 − origin) and f the layer's factor times its group's.
    const double fx = 0.5 * 0.5, fy = 0.0 * 1.0;  // group 0.5 × layer 0.5; layer y 0
    std::vector<uint32_t> cells(10 * 5, 0);
    cells[2 * 10 + 5] = 1;
    Tilemap m = map_with(10, 5, cells);
    m.parallax_origin_x = 6, m.parallax_origin_y = -3;
    LayerInfo group;
    group.kind = LayerKind::Group;
    group.parallax_x = 0.5;
    LayerInfo layer;
    layer.kind = LayerKind::Tile;
    layer.parallax_x = 0.5, layer.parallax_y = 0.0;
    group.children.push_back(layer);
    m.layer_tree.push_back(group);
    for (const auto& [cx, cy] : {std::pair<int64_t, int64_t>{0, 0}, {7, 3}, {-13, 11}, {31, -2}}) {
        Canvas c(40, 32);
        TileArt art;
        art.bind(&m);
        c.clear(kBackground);
        draw_map(c, art, m, cx, cy);
        const double sx = (1 - fx) * (double(cx) + 20 - 6), sy = (1 - fy) * (double(cy) + 16 - -3);
        const int left = 20 - int(std::floor(double(cx) - sx)), top = 8 - int(std::floor(double(cy) - sy));
        CAPTURE(cx);
        CAPTURE(cy);
        CHECK(c.pixel(left, top) == sheet_color(0, 0, 0));
        CHECK(c.pixel(left + 3, top + 3) == sheet_color(0, 3, 3));
        CHECK(c.pixel(left - 1, top) == kBackground);
        CHECK(c.pixel(left, top - 1) == kBackground);
    }
}

TEST_CASE("an image layer repeats from its offset in both directions under any camera") {
    const std::string dir = temp_dir().string();
    write_sheet("backdrop.png");  // 8 × 8 px
    Tilemap m;
    m.path = dir + "/map.tmx";
    m.width = m.height = 4, m.tile_width = m.tile_height = 4;
    LayerInfo img;
    img.kind = LayerKind::Image;
    img.image = "backdrop.png";
    img.offset_x = 3, img.offset_y = -2;
    img.repeat_x = img.repeat_y = true;
    m.layer_tree.push_back(img);
    for (const auto& [cx, cy] : {std::pair<int64_t, int64_t>{0, 0}, {-5, 9}, {21, -30}}) {
        Canvas c(20, 12);
        TileArt art;
        art.bind(&m);
        draw_map(c, art, m, cx, cy);
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 20; ++x) {
                // World px (x + cx, y + cy) shows image px ((wx − 3) mod 8, (wy + 2) mod 8).
                const int64_t u = ((x + cx - 3) % 8 + 8) % 8, v = ((y + cy + 2) % 8 + 8) % 8;
                const int t = int((v / 4) * 2 + u / 4);
                CAPTURE(cx);
                CAPTURE(cy);
                CHECK(c.pixel(x, y) == sheet_color(t, int(u % 4), int(v % 4)));
            }
    }
}

TEST_CASE("entities draw in the object layer the view names, so the layers after it draw over them") {
    // Layer 0: tile 1 everywhere; object layer "actors"; layer 1: tile 4 at
    // cell (1, 0) only. An entity box covering cells (0, 0)–(1, 0).
    Tilemap m = map_with(2, 1, {1, 1});
    TileLayer front;
    front.width = 2, front.height = 1;
    front.cells = std::vector<uint32_t>{0, 4};
    m.layers.push_back(front);
    ObjectLayer objects;
    objects.name = "actors";
    m.object_layers.push_back(objects);
    const auto info = [](LayerKind kind, const char* name, size_t index) {
        LayerInfo l;
        l.kind = kind, l.name = name, l.index = index;
        return l;
    };
    m.layer_tree = {info(LayerKind::Tile, "back", 0), info(LayerKind::Object, "actors", 0),
                    info(LayerKind::Tile, "front", 1)};
    const std::vector<EntityView> entities{{.x = 0, .y = 0, .w = 8, .h = 4, .solid = true, .color = Rgba{255, 0, 255, 255}}};
    for (const bool between : {false, true}) {
        SceneView v;
        v.map = &m;
        v.entities = entities;
        if (between) v.entity_layer = "actors";
        Canvas c(8, 4);
        TileArt art;
        draw_scene(c, art, v);
        // The box's pixel at (4, 0) is the front tile's when the entities
        // are between the layers, the box's when they are on top.
        CAPTURE(between);
        CHECK((c.pixel(4, 0) == sheet_color(3, 0, 0)) == between);
        CHECK(c.pixel(0, 0) != sheet_color(0, 0, 0));  // cell 0 has no front tile: the box shows
    }
    CHECK(entity_split(drawn_layers(m), "actors") == 2);
    CHECK(entity_split(drawn_layers(m), "") == 3);
    CHECK(entity_split(drawn_layers(m), "back") == 3);  // a tile layer cannot hold them
}

TEST_CASE("the map's background colour is the clear colour unless the view sets one") {
    Tilemap m = map_with(1, 1, {0});
    m.background = MapColor{10, 20, 30, 255};
    SceneView v;
    v.map = &m;
    Canvas c(4, 4);
    TileArt art;
    draw_scene(c, art, v);
    CHECK(c.pixel(2, 2) == Rgba{10, 20, 30, 255});
    v.background = Rgba{1, 2, 3, 255};
    draw_scene(c, art, v);
    CHECK(c.pixel(2, 2) == Rgba{1, 2, 3, 255});
    m.background.reset();
    v.background.reset();
    draw_scene(c, art, v);
    CHECK(c.pixel(2, 2) == kBackground);
}

TEST_CASE("a template instance and an animated tile object draw as the tile they name") {
    const std::string dir = temp_dir().string();
    write_sheet("sheet.png");
    write(dir + "/sheet.tsx",
          "<tileset name=\"sheet\" tilewidth=\"4\" tileheight=\"4\" tilecount=\"4\" columns=\"2\">\n"
          " <image source=\"sheet.png\" width=\"8\" height=\"8\"/>\n"
          " <tile id=\"2\"><animation><frame tileid=\"2\" duration=\"100\"/><frame tileid=\"3\" duration=\"100\"/>"
          "</animation></tile>\n</tileset>\n");
    write(dir + "/thing.tx", "<template><tileset firstgid=\"1\" source=\"sheet.tsx\"/>"
                             "<object gid=\"2\" width=\"4\" height=\"4\"/></template>\n");
    write(dir + "/objects.tmx",
          "<map orientation=\"orthogonal\" width=\"4\" height=\"1\" tilewidth=\"4\" tileheight=\"4\">\n"
          " <tileset firstgid=\"1\" source=\"sheet.tsx\"/>\n"
          " <objectgroup name=\"o\" draworder=\"index\">\n"
          "  <object id=\"1\" template=\"thing.tx\" x=\"0\" y=\"4\"/>\n"
          "  <object id=\"2\" gid=\"3\" x=\"8\" y=\"4\" width=\"4\" height=\"4\"/>\n"
          " </objectgroup>\n</map>\n");
    const Tilemap m = load_tilemap(dir + "/objects.tmx");
    for (const double t : {0.0, 150.0}) {
        Canvas c(16, 4);
        TileArt art;
        art.bind(&m);
        c.clear(kBackground);
        draw_map(c, art, m, 0, 0, t);
        CAPTURE(t);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                CHECK(c.pixel(x, y) == sheet_color(1, x, y));                    // the template's tile 1
                CHECK(c.pixel(8 + x, y) == sheet_color(t < 100 ? 2 : 3, x, y));  // animated: 2, then 3
            }
    }
}

TEST_CASE("the object index finds every object that shows in a view, and none far from it") {
    // 400 tile objects over 2000 × 2000 px: stretched, flipped, turned, in
    // topdown order. Drawn through the index, every view is the picture
    // drawn by visiting every object.
    Tilemap m = map_with(1, 1, {0});
    ObjectLayer layer;
    layer.name = "things";
    for (uint32_t i = 0; i < 400; ++i) {
        MapObject o;
        o.id = int(i + 1);
        o.shape = ObjectShape::Tile;
        o.gid = (1 + i % 4) | (i % 3 == 0 ? kFlipHorizontal : 0) | (i % 7 == 0 ? kFlipDiagonal : 0);
        o.x = (i * 7919) % 2000, o.y = (i * 104729) % 2000;
        o.width = 4 + i % 9, o.height = 4 + i % 5;
        o.rotation = i % 5 == 0 ? double(i % 360) : 0;
        layer.objects.push_back(o);
    }
    m.object_layers.push_back(layer);
    LayerInfo info;
    info.kind = LayerKind::Object;
    m.layer_tree = {info};
    Tilemap indexed = m;
    indexed.object_layers[0].index = index_objects(indexed, indexed.object_layers[0]);
    for (int k = 0; k < 25; ++k) {
        const int64_t cx = (k * 389) % 2100 - 50, cy = (k * 577) % 2100 - 50;
        Canvas a(64, 48), b(64, 48);
        TileArt art;
        art.bind(&m);
        a.clear(kBackground);
        draw_map(a, art, m, cx, cy);
        art.bind(&indexed);
        b.clear(kBackground);
        draw_map(b, art, indexed, cx, cy);
        CAPTURE(cx);
        CAPTURE(cy);
        int same = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x) same += a.pixel(x, y) == b.pixel(x, y);
        CHECK(same == 64 * 48);
    }
    std::vector<uint32_t> found;
    objects_in_view(indexed.object_layers[0].index, 5000, 5000, 5640, 5360, found);
    CHECK(found.empty());  // far beyond every object: nothing is visited
    objects_in_view(indexed.object_layers[0].index, 0, 0, 640, 360, found);
    CHECK(found.size() < 400 / 4);  // a view of 640 × 360 of 2000² px sees few of them
}

TEST_CASE("how many tiles an atlas image holds, cut as Tiled cuts it") {
    Tileset ts;
    ts.tile_width = ts.tile_height = 4;
    CHECK(tiles_in_image(ts, 8, 8, 2) == 4);
    CHECK(tiles_in_image(ts, 8, 8, 0) == 4);   // columns as many as fit
    CHECK(tiles_in_image(ts, 9, 11, 0) == 4);  // a part-tile at the edge holds none
    CHECK(tiles_in_image(ts, 8, 8, 3) == 2);   // a third column past the right edge: tile 2 is past it
    CHECK(tiles_in_image(ts, 8, 3, 2) == 0);   // not one row high
    ts.margin = 1, ts.spacing = 2;
    CHECK(tiles_in_image(ts, 12, 8, 0) == 2);  // columns at x 1 and 7, one row at y 1 (the next would end at 11)
    CHECK(tiles_in_image(ts, 12, 11, 0) == 4);
    ts.tile_width = 0;
    CHECK(tiles_in_image(ts, 12, 11, 0) == 0);
}

TEST_CASE("bad input names the file and the value") {
    const std::string dir = temp_dir().string();
    const auto map_text = [](const std::string& layers, const std::string& attrs = "") {
        return "<map orientation=\"orthogonal\" width=\"1\" height=\"1\" tilewidth=\"4\" tileheight=\"4\"" + attrs +
               ">\n <tileset firstgid=\"1\" name=\"s\" tilewidth=\"4\" tileheight=\"4\" tilecount=\"4\" columns=\"2\">"
               "<image source=\"sheet.png\" width=\"8\" height=\"8\"/></tileset>\n" +
               layers + "</map>\n";
    };
    SUBCASE("a malformed colour") {
        write(dir + "/colour.tmx", map_text("", " backgroundcolor=\"#12x\""));
        CHECK_THROWS_WITH(load_tilemap(dir + "/colour.tmx"),
                          doctest::Contains("backgroundcolor='#12x' is not a colour"));
        CHECK_THROWS_WITH(load_tilemap(dir + "/colour.tmx"), doctest::Contains("colour.tmx:1"));
        write(dir + "/tint.tmx", map_text("<layer name=\"l\" width=\"1\" height=\"1\" tintcolor=\"#ff00zz\">"
                                          "<data encoding=\"csv\">0</data></layer>\n"));
        CHECK_THROWS_WITH(load_tilemap(dir + "/tint.tmx"), doctest::Contains("tintcolor='#ff00zz' is not a colour"));
    }
    SUBCASE("a tintcolor without '#': no colour, as Tiled reads it; the layer is drawn untinted, with a warning") {
        write_sheet("sheet.png");
        for (const char* ext : {".tmx", ".tmj"}) {
            const std::string path = dir + "/hashless" + ext;
            if (std::string(ext) == ".tmx")
                write(path, map_text("<group name=\"g\" tintcolor=\"80ff0000\"><layer name=\"l\" width=\"1\" "
                                     "height=\"1\" tintcolor=\"ff0000\"><data encoding=\"csv\">1</data></layer></group>\n"));
            else
                write(path, "{\"orientation\": \"orthogonal\", \"width\": 1, \"height\": 1, \"tilewidth\": 4, "
                            "\"tileheight\": 4, \"tilesets\": [{\"firstgid\": 1, \"name\": \"s\", \"tilewidth\": 4, "
                            "\"tileheight\": 4, \"tilecount\": 4, \"columns\": 2, \"image\": \"sheet.png\", "
                            "\"imagewidth\": 8, \"imageheight\": 8}], \"layers\": [{\"type\": \"group\", \"name\": \"g\", "
                            "\"tintcolor\": \"80ff0000\", \"layers\": [{\"type\": \"tilelayer\", \"name\": \"l\", "
                            "\"width\": 1, \"height\": 1, \"tintcolor\": \"ff0000\", \"data\": [1]}]}]}");
            CAPTURE(path);
            const Tilemap m = load_tilemap(path);
            REQUIRE(m.warnings.size() == 2);
            CHECK(m.warnings[0] == path + ": layer 'g' has tintcolor '80ff0000', which has no '#' and so is no "
                                          "colour (as Tiled reads it); drawn untinted");
            CHECK(m.warnings[1] == path + ": layer 'l' has tintcolor 'ff0000', which has no '#' and so is no "
                                          "colour (as Tiled reads it); drawn untinted");
            CHECK(m.layer_tree[0].tint_color == "80ff0000");  // kept as written
            CHECK(!m.layer_tree[0].children[0].tint);
            Canvas c(kTile, kTile);
            TileArt art;
            art.bind(&m);
            c.clear(kBackground);
            draw_map(c, art, m, 0, 0);
            for (int y = 0; y < kTile; ++y)
                for (int x = 0; x < kTile; ++x) CHECK(c.pixel(x, y) == sheet_color(0, x, y));
        }
    }
    SUBCASE("an unknown alignment") {
        write(dir + "/align.tmx",
              "<map orientation=\"orthogonal\" width=\"1\" height=\"1\" tilewidth=\"4\" tileheight=\"4\">\n"
              " <tileset firstgid=\"1\" name=\"s\" tilewidth=\"4\" tileheight=\"4\" objectalignment=\"middle\"/>\n</map>\n");
        CHECK_THROWS_WITH(load_tilemap(dir + "/align.tmx"), doctest::Contains("objectalignment='middle' is not one of"));
    }
    SUBCASE("a tile object whose gid no tileset holds: a warning, drawn as a missing tile; an error when strict") {
        write(dir + "/gid.tmx", map_text("<objectgroup name=\"things\"><object id=\"7\" gid=\"99\" x=\"0\" y=\"4\" "
                                         "width=\"4\" height=\"4\"/></objectgroup>\n"));
        const Tilemap m = load_tilemap(dir + "/gid.tmx");
        REQUIRE(m.warnings.size() == 1);
        CHECK(m.warnings[0] == dir + "/gid.tmx: tile object 7 of layer 'things' has gid 99, beyond every tileset; "
                                     "drawn as a missing tile");
        LoadOptions strict;
        strict.strict = true;
        CHECK_THROWS_WITH(load_tilemap(dir + "/gid.tmx", strict),
                          doctest::Contains("tile object 7 of layer 'things' has gid 99, beyond every tileset"));
        Canvas c(4, 4);
        TileArt art;
        art.bind(&m);
        c.clear(kBackground);
        draw_map(c, art, m, 0, 0);
        Rgba edge = kMissingTileColor;
        CHECK(c.pixel(0, 0) == edge);
    }
    SUBCASE("a tilecount larger than the tileset's image holds: one warning naming the first tile past its end") {
        write_sheet("sheet.png");
        write(dir + "/past.tmx",
              "<map orientation=\"orthogonal\" width=\"1\" height=\"1\" tilewidth=\"4\" tileheight=\"4\">\n"
              " <tileset firstgid=\"1\" name=\"s\" tilewidth=\"4\" tileheight=\"4\" tilecount=\"7\" columns=\"2\">"
              "<image source=\"sheet.png\" width=\"8\" height=\"8\"/></tileset>\n"
              " <layer name=\"l\" width=\"1\" height=\"1\"><data encoding=\"csv\">6</data></layer>\n</map>\n");
        const Tilemap m = load_tilemap(dir + "/past.tmx");
        REQUIRE(m.warnings.size() == 1);
        CHECK(m.warnings[0] == dir + "/past.tmx: tileset 's': tile 4 and on are past the end of its image 'sheet.png' "
                                     "(8x8 px holds 4 of its 7 tiles); drawn as missing tiles");
        CHECK(m.gid_known(6));  // the tileset's gid all the same: no "beyond every tileset"
        LoadOptions strict;
        strict.strict = true;  // the tiles are the tileset's: not an error even so
        CHECK(load_tilemap(dir + "/past.tmx", strict).warnings.size() == 1);
    }
    SUBCASE("an image layer's missing image") {
        write(dir + "/image.tmx", map_text("<imagelayer name=\"sky\"><image source=\"nowhere.png\" width=\"4\" "
                                           "height=\"4\"/></imagelayer>\n"));
        const Tilemap m = load_tilemap(dir + "/image.tmx");
        Canvas c(4, 4);
        TileArt art;
        art.bind(&m);
        CHECK_THROWS_WITH_AS(draw_map(c, art, m, 0, 0),
                             ("cannot read image layer image '" + dir + "/nowhere.png': No such file or directory").c_str(),
                             RenderError);
    }
}

}  // TEST_SUITE
