// SPDX-License-Identifier: MIT
// What the TMX reader reads beyond tiles (issue 22): object shapes, templates,
// class and list properties, the layer tree, tileset extras, gids beyond
// every tileset, sparse image collections and text encodings, on the maps
// of tests/data/make_feature_maps.py, with exact values.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "tilemap/tilemap.hpp"
#include "tilemap/utf8.hpp"

namespace {

using namespace ds;

std::string feature(const std::string& rel) {
    return std::string(DS_TEST_DATA) + "/maps/features/" + rel;
}

Tilemap load(const std::string& rel, bool strict = false) {
    LoadOptions options;
    options.strict = strict;
    return load_tilemap(feature(rel), options);
}

struct Failure {
    std::string what;
    int line = -1;
};

Failure failure_of(const std::string& rel, bool strict = false) {
    try {
        load(rel, strict);
    } catch (const MapError& e) {
        return {e.what(), e.line()};
    }
    return {"(loaded without error)", -1};
}

const MapObject& object(const Tilemap& m, const std::string& name) {
    for (const ObjectLayer& l : m.object_layers)
        for (const MapObject& o : l.objects)
            if (o.name == name) return o;
    FAIL("no object " << name);
    throw;
}

std::string props_text(const Properties& props);

std::string prop_text(const Property& p) {
    std::string s = p.name + ":" + p.type;
    if (!p.property_type.empty()) s += "<" + p.property_type + ">";
    if (p.type == "class" || p.type == "list") return s + "{" + props_text(p.members) + "}";
    return s + "=" + p.value;
}

std::string props_text(const Properties& props) {
    std::string s;
    for (const Property& p : props) s += (s.empty() ? "" : " ") + prop_text(p);
    return s;
}

}  // namespace

TEST_SUITE("tmx-features") {

TEST_CASE("objects keep their shape, points, text, rotation, visibility and tile gid") {
    const Tilemap m = load("objects.tmx");
    REQUIRE(m.object_layers.size() == 1);
    REQUIRE(m.object_layers[0].objects.size() == 7);
    const MapObject& box = object(m, "box");
    CHECK(box.shape == ObjectShape::Rectangle);
    CHECK(box.type == "crate");
    CHECK(box.width == 3);
    CHECK(box.height == 4);
    const MapObject& oval = object(m, "oval");
    CHECK(oval.shape == ObjectShape::Ellipse);
    CHECK(oval.rotation == 45);
    const MapObject& spot = object(m, "spot");
    CHECK(spot.shape == ObjectShape::Point);
    CHECK_FALSE(spot.visible);
    const MapObject& tri = object(m, "tri");
    CHECK(tri.shape == ObjectShape::Polygon);
    REQUIRE(tri.points.size() == 3);
    CHECK(tri.points[1].x == 10.5);
    CHECK(tri.points[1].y == 0);
    CHECK(tri.points[2].x == -2);
    CHECK(tri.points[2].y == -3.25);
    const MapObject& path = object(m, "path");
    CHECK(path.shape == ObjectShape::Polyline);
    REQUIRE(path.points.size() == 2);
    CHECK(path.points[1].x == 4);
    const MapObject& sign = object(m, "sign");
    CHECK(sign.shape == ObjectShape::Text);
    CHECK(sign.text.text == "Hello\nthere");
    CHECK(sign.text.font_family == "Serif");
    CHECK(sign.text.pixel_size == 12);
    CHECK(sign.text.wrap);
    CHECK(sign.text.bold);
    CHECK_FALSE(sign.text.italic);
    CHECK(sign.text.kerning);
    CHECK(sign.text.color == "#ff0000");
    CHECK(sign.text.halign == "center");
    CHECK(sign.text.valign == "bottom");
    const MapObject& tile = object(m, "tile");
    CHECK(tile.shape == ObjectShape::Tile);
    CHECK(tile.gid == (kFlipHorizontal | kFlipDiagonal | 3u));
    CHECK(m.object_layers[0].objects[0].template_path.empty());
}

TEST_CASE("a polygon's points are parsed strictly") {
    const std::string text =
        "<map orientation=\"orthogonal\" width=\"1\" height=\"1\" tilewidth=\"16\" tileheight=\"16\">\n"
        " <objectgroup name=\"o\">\n"
        "  <object id=\"1\"><polygon points=\"0,0 1;2\"/></object>\n"
        " </objectgroup>\n"
        "</map>\n";
    CHECK_THROWS_WITH_AS(parse_tilemap(text, "mem.tmx"),
                         "mem.tmx:3: <polygon> points='0,0 1;2' has '1;2', not an x,y pair of numbers",
                         MapError);
}

TEST_CASE("template instances: the template's fields are defaults, the instance's override") {
    const Tilemap m = load("templates.tmx");
    const std::vector<MapObject>& objs = m.object_layers.at(0).objects;
    REQUIRE(objs.size() == 5);
    const std::string spawn = feature("templates/spawn.tx");
    // Only what the instance writes (x, y, its properties) is its own.
    CHECK(objs[0].name == "spawn");
    CHECK(objs[0].type == "spawner");
    CHECK(objs[0].shape == ObjectShape::Ellipse);
    CHECK(objs[0].x == 100);
    CHECK(objs[0].width == 20);
    CHECK(objs[0].height == 10);
    CHECK(objs[0].rotation == 15);
    CHECK(objs[0].template_path == spawn);
    CHECK(props_text(objs[0].properties) == "kind:string=bat count:int=5 boss:bool=true");
    CHECK(objs[1].name == "big");
    // width="40" alone: a size with a side <= 0 is not an override (Tiled).
    CHECK(objs[1].width == 20);
    CHECK(objs[1].height == 10);
    CHECK_FALSE(objs[1].visible);
    CHECK(props_text(objs[1].properties) == "kind:string=bat count:int=2");
    // The template's tile, counted in the template's own terrain.tsx, maps
    // to the map's gid for the same file.
    CHECK(objs[2].shape == ObjectShape::Tile);
    CHECK(objs[2].gid == (kFlipHorizontal | 4u));
    CHECK(objs[2].name == "crate");
    CHECK(objs[2].x == 30);
    CHECK(props_text(objs[2].properties) == "weight:int=3");
    // A shape the instance writes wins over the template's.
    CHECK(objs[3].shape == ObjectShape::Point);
    // A template's own template= is not followed (templates do not nest).
    CHECK(objs[4].name == "self");
    CHECK(objs[4].width == 1);
    CHECK(objs[4].template_path == feature("templates/self.tx"));
    // A tileset tile's objects may be instances too.
    const TileInfo* shapes = m.tilesets.at(1).tile(0);
    REQUIRE(shapes != nullptr);
    REQUIRE(shapes->objects.size() == 1);
    CHECK(shapes->objects[0].shape == ObjectShape::Ellipse);
    CHECK(shapes->objects[0].x == 2);
    CHECK(shapes->objects[0].width == 20);
    CHECK(shapes->objects[0].template_path == spawn);
}

TEST_CASE("a template's tileset the map lacks is added after the last firstgid") {
    const Tilemap m = load("template_adds_tileset.tmx");
    REQUIRE(m.tilesets.size() == 2);
    CHECK(m.tilesets[1].firstgid == 4);
    CHECK(m.tilesets[1].name == "terrain");
    CHECK(m.tilesets[1].source == "../tilesets/terrain.tsx");
    CHECK(m.object_layers.at(0).objects.at(0).gid == (kFlipHorizontal | 7u));
    CHECK(m.gid_solid(4));  // terrain's tile 0 is solid
}

TEST_CASE("a template that cannot be read names the map, the line and the template") {
    const Failure missing = failure_of("missing_template.tmx");
    CHECK(missing.line == 8);
    CHECK(missing.what.find("missing_template.tmx:8: cannot open template '" +
                            feature("templates/nowhere.tx") + "': ") != std::string::npos);
    const Failure dev_zero = failure_of("dev_zero_template.tmx");
    CHECK(dev_zero.line == 8);
    CHECK(dev_zero.what.find("cannot open template '/dev/zero': is not a regular file") !=
          std::string::npos);
}

TEST_CASE("templates count against max-bytes, each read once however often it is used") {
    // templates.tmx (1164 bytes), terrain.tsx (1246), spawn.tx (280, used
    // four times), crate.tx (292, whose terrain.tsx is the map's) and
    // self.tx (125): 3107 bytes when each file is read once.
    LoadOptions options;
    options.limits.max_bytes = 3107;
    CHECK(load_tilemap(feature("templates.tmx"), options).object_layers.at(0).objects.size() == 5);
    options.limits.max_bytes = 3106;
    CHECK_THROWS_WITH_AS(load_tilemap(feature("templates.tmx"), options),
                         doctest::Contains("self.tx': is 125 bytes, more than the 124 bytes max-bytes leaves"),
                         MapError);
}

TEST_CASE("template instances override only what Tiled takes as an override") {
    const Tilemap m = load("template_rules.tmx");
    const std::vector<MapObject>& objs = m.object_layers.at(0).objects;
    REQUIRE(objs.size() == 4);
    // name="" type="" width="0": the template's name, class and whole size;
    // the position is the instance's, never the template's (70, 80).
    CHECK(objs[0].name == "placed");
    CHECK(objs[0].type == "marker");
    CHECK(objs[0].x == 5);
    CHECK(objs[0].y == 6);
    CHECK(objs[0].width == 20);
    CHECK(objs[0].height == 10);
    CHECK(objs[0].rotation == 30);
    CHECK_FALSE(objs[0].visible);
    CHECK(objs[0].shape == ObjectShape::Ellipse);
    CHECK(props_text(objs[0].properties) == "a:string=template b:int=1");
    // Nothing written: at (0, 0).
    CHECK(objs[1].x == 0);
    CHECK(objs[1].y == 0);
    CHECK(objs[1].width == 20);
    CHECK(objs[1].height == 10);
    // height="0" beside a positive width: the template's size, both sides.
    CHECK(objs[2].x == 1);
    CHECK(objs[2].y == 2);
    CHECK(objs[2].width == 20);
    CHECK(objs[2].height == 10);
    // Everything written: the instance's, rotation 0 and visible="1" too;
    // gid="0" is no tile, so the shape stays the template's ellipse.
    CHECK(objs[3].name == "own");
    CHECK(objs[3].type == "mine");
    CHECK(objs[3].x == 3);
    CHECK(objs[3].y == 4);
    CHECK(objs[3].width == 8);
    CHECK(objs[3].height == 6);
    CHECK(objs[3].rotation == 0);
    CHECK(objs[3].visible);
    CHECK(objs[3].gid == 0);
    CHECK(objs[3].shape == ObjectShape::Ellipse);
    CHECK(props_text(objs[3].properties) == "a:string=template b:int=2 c:string=instance");
}

TEST_CASE("class and list properties keep their members, recursively") {
    const Tilemap m = load("properties.tmx");
    CHECK(props_text(m.properties) ==
          "spawn:class<Spawn>{hp:int=3 pos:class<Point>{x:float=1.5}} "
          "empty:class<Nothing>{} "
          "path:list{:int=4 :string=two :class<Point>{y:float=-2}} "
          "poem:string=roses\nare red "
          "mood:int<Mood>=2 "
          "name:string=custom");
}

TEST_CASE("class properties nested too deep are refused") {
    const Failure f = failure_of("deep_class.tmx");
    CHECK(f.line == 3);
    CHECK(f.what.find("properties nested more than 32 deep") != std::string::npos);
}

TEST_CASE("the layer tree, group offsets and tileset extras") {
    const Tilemap m = load("layers.tmx");
    CHECK(m.type == "level");
    CHECK(m.background_color == "#ff336699");
    REQUIRE(m.layer_tree.size() == 2);
    const LayerInfo& world = m.layer_tree[0];
    CHECK(world.kind == LayerKind::Group);
    CHECK(world.id == 10);
    CHECK(world.name == "world");
    CHECK(world.type == "zone");
    CHECK(world.offset_x == 10);
    CHECK(world.opacity == 0.5);
    CHECK(world.parallax_x == 0.5);
    CHECK(world.parallax_y == 0.25);
    CHECK(world.tint_color == "#80ff0000");
    CHECK(props_text(world.properties) == "depth:int=1");
    REQUIRE(world.children.size() == 3);
    CHECK(world.children[0].kind == LayerKind::Tile);
    CHECK(world.children[0].index == 0);
    CHECK(world.children[0].offset_x == 1);  // its own
    CHECK(world.children[1].kind == LayerKind::Object);
    CHECK(world.children[1].index == 0);
    const LayerInfo& inner = world.children[2];
    CHECK(inner.kind == LayerKind::Group);
    CHECK_FALSE(inner.visible);
    REQUIRE(inner.children.size() == 2);
    CHECK(inner.children[0].kind == LayerKind::Image);
    CHECK(inner.children[0].image == "sky.png");
    CHECK(inner.children[0].image_width == 320);
    CHECK(inner.children[0].repeat_x);
    CHECK_FALSE(inner.children[0].repeat_y);
    CHECK(inner.children[1].index == 1);
    CHECK(m.layer_tree[1].name == "top");
    CHECK(m.layer_tree[1].index == 2);
    // Tile layers hold their groups' values combined with their own.
    REQUIRE(m.layers.size() == 3);
    CHECK(m.layers[0].offset_x == 11);
    CHECK(m.layers[0].offset_y == 7);
    CHECK(m.layers[0].opacity == 0.25);
    CHECK(m.layers[0].visible);
    CHECK(m.layers[1].name == "deco");
    CHECK(m.layers[1].offset_x == 110);
    CHECK_FALSE(m.layers[1].visible);
    CHECK(m.layers[2].offset_x == 0);
    const Tileset& ts = m.tilesets.at(0);
    CHECK(ts.type == "water");
    CHECK(ts.tile_offset_x == 3);
    CHECK(ts.tile_offset_y == -4);
    CHECK(props_text(ts.properties) == "biome:string=sea");
    const TileInfo* t = ts.tile(1);
    REQUIRE(t != nullptr);
    REQUIRE(t->animation.size() == 2);
    CHECK(t->animation[1].tile_id == 2);
    CHECK(t->animation[1].duration_ms == 250);
}

TEST_CASE("gids beyond every tileset load as missing, non-solid tiles with one warning per layer") {
    const Tilemap m = load("missing_gids.tmx");
    const std::string path = feature("missing_gids.tmx");
    REQUIRE(m.warnings.size() == 2);
    CHECK(m.warnings[0] == path +
                               ":5: gid 9 at cell (1, 0) of layer 'ground' is beyond every tileset "
                               "(3 cells in all); loaded as a missing, non-solid tile");
    CHECK(m.warnings[1] == path +
                               ":14: gid 10 at cell (2, 0) of layer 'walls' is beyond every "
                               "tileset; loaded as a missing, non-solid tile");
    // The raw gids stay, for a renderer to draw as missing.
    CHECK(m.layers[0].raw_gid(1, 0) == 9);
    CHECK(m.layers[0].raw_gid(1, 1) == (kFlipHorizontal | 9u));
    CHECK_FALSE(m.gid_solid(9));
    CHECK_FALSE(m.cell_solid(1, 0));
    CHECK_FALSE(m.cell_solid(2, 0));  // even in a solid layer
    CHECK(m.cell_solid(0, 0));
    const TileGrid grid = m.solid_grid();
    CHECK(grid.cell(0, 0) == kSolidCell);
    CHECK(grid.cell(1, 0) == kEmptyCell);
    CHECK(grid.cell(2, 0) == kEmptyCell);
    CHECK(grid.cell(0, 1) == kEmptyCell);
    // Unknown gids still cannot be put into a map.
    Tilemap edited = m;
    TileGrid g = grid;
    CHECK_THROWS_AS(set_tile(edited, g, 0, 0, 0, 9), std::invalid_argument);
}

TEST_CASE("strict loading keeps the old refusal, and so does nothing else") {
    const Failure f = failure_of("missing_gids.tmx", true);
    CHECK(f.line == 5);
    CHECK(f.what.find("gid 9 at cell (1, 0) of layer 'ground' is beyond every tileset") !=
          std::string::npos);
    // The 3-argument overload is not strict either.
    CHECK(load_tilemap(feature("missing_gids.tmx")).warnings.size() == 2);
}

TEST_CASE("a sparse image collection loads, ids past tilecount included") {
    const Tilemap m = load("sparse_collection.tmx");
    const Tileset& ts = m.tilesets.at(0);
    CHECK(ts.image_collection());
    CHECK(ts.has_tile(5));
    CHECK_FALSE(ts.has_tile(2));
    CHECK(m.layers[0].raw_gid(1, 0) == 6);
    CHECK(m.cell_solid(1, 0));
    CHECK_FALSE(m.cell_solid(0, 0));
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0].find("gid 3 at cell (2, 0) of layer 'ground'") != std::string::npos);
}

TEST_CASE("text in the encoding its XML declaration names comes back as UTF-8") {
    CHECK(find_property(load("latin1.tmx").properties, "word")->value == "caf\xC3\xA9");
    CHECK(find_property(load("windows1252.tmx").properties, "word")->value == "5\xE2\x82\xAC");
    CHECK(find_property(load("utf16.tmx").properties, "word")->value == "na\xC3\xAFve");
}

TEST_CASE("a byte not valid in the file's encoding is refused with its line") {
    const Failure bad = failure_of("bad_byte.tmx");
    CHECK(bad.line == 4);
    CHECK(bad.what == feature("bad_byte.tmx") + ":4: byte 0xE9 is not valid UTF-8");
    const Failure cp = failure_of("bad_cp1252.tmx");
    CHECK(cp.line == 4);
    CHECK(cp.what == feature("bad_cp1252.tmx") + ":4: byte 0x81 is not valid windows-1252 text");
    const Failure unknown = failure_of("unknown_encoding.tmx");
    CHECK(unknown.line == 1);
    CHECK(unknown.what ==
          feature("unknown_encoding.tmx") + ":1: unknown encoding 'KLINGON-8' in the XML declaration");
}

TEST_CASE("only the XML declaration's own encoding= is read") {
    // Unclosed: tinyxml2 says what is wrong, not the encoding check.
    const std::string unclosed =
        "<?xml version=\"1.0\"\n<map><layer><data encoding=\"csv\">1</data></layer></map>\n";
    CHECK_THROWS_WITH_AS(parse_tilemap(unclosed, "mem.tmx"), doctest::Contains("mem.tmx:1: malformed XML"),
                         MapError);
}

TEST_CASE("the UTF-8 check refuses overlong forms, surrogates and stray bytes") {
    using tmx::first_invalid_utf8;
    CHECK(first_invalid_utf8("plain") == std::string_view::npos);
    CHECK(first_invalid_utf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80") == std::string_view::npos);
    CHECK(first_invalid_utf8("ab\xE9") == 2);
    CHECK(first_invalid_utf8("\xC0\xAF") == 0);          // overlong '/'
    CHECK(first_invalid_utf8("x\xED\xA0\x80") == 1);     // a surrogate
    CHECK(first_invalid_utf8("\xF4\x90\x80\x80") == 0);  // past U+10FFFF
    CHECK(first_invalid_utf8("\xE2\x82") == 0);          // cut short
    CHECK(tmx::line_at("a\nb\nc", 4) == 3);
}

TEST_CASE("a JSON file is told by its content, after a BOM and spaces") {
    CHECK_THROWS_WITH_AS(parse_tilemap("\xEF\xBB\xBF  {\"type\": \"map\"}", "map.tmx"),
                         "map.tmx: the document has no \"width\"", MapError);
}

}  // TEST_SUITE
