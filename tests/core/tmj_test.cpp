// SPDX-License-Identifier: MIT
// Tiled's JSON formats (.tmj maps, .tsj tilesets, .tj templates) and the
// Tiled project file. The twins in tests/data/maps/json are written by
// tests/data/make_json_maps.py from the TMX test maps; each pair must load
// into the same model. objects.tmj, templates/ and project.tiled-project
// are written by hand.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tilemap/project.hpp"
#include "tilemap/tilemap.hpp"

namespace {

using namespace ds;

std::string map_path(const std::string& rel) { return std::string(DS_TEST_DATA) + "/maps/" + rel; }
std::string json_path(const std::string& rel) { return map_path("json/" + rel); }

// The message of the MapError loading `text` (named `path`) throws.
std::string parse_error(const std::string& text, const std::string& path = "m.tmj") {
    try {
        parse_tilemap(text, path);
    } catch (const MapError& e) {
        return e.what();
    }
    return "(no error)";
}

// A file in the test's own temporary folder, for loads that need a path.
struct TempFile {
    explicit TempFile(const std::string& name, const std::string& text)
        : path((std::filesystem::temp_directory_path() / ("ds-tmj-" + name)).string()) {
        std::ofstream(path, std::ios::binary) << text;
    }
    ~TempFile() { std::remove(path.c_str()); }
    std::string path;
};

void same_properties(const Properties& a, const Properties& b, const std::string& where);

void same_property(const Property& a, const Property& b, const std::string& where) {
    INFO(where << " property '" << a.name << "'");
    CHECK(a.name == b.name);
    CHECK(a.type == b.type);
    CHECK(a.value == b.value);
    CHECK(a.property_type == b.property_type);
    same_properties(a.members, b.members, where + "." + a.name);
}

void same_properties(const Properties& a, const Properties& b, const std::string& where) {
    INFO(where);
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) same_property(a[i], b[i], where);
}

void same_object(const MapObject& a, const MapObject& b);

void same_tileset(const Tileset& a, const Tileset& b) {
    INFO("tileset '" << a.name << "'");
    CHECK(a.firstgid == b.firstgid);
    CHECK(a.name == b.name);
    CHECK(a.tile_width == b.tile_width);
    CHECK(a.tile_height == b.tile_height);
    CHECK(a.tile_count == b.tile_count);
    CHECK(a.columns == b.columns);
    CHECK(a.spacing == b.spacing);
    CHECK(a.margin == b.margin);
    CHECK(a.image == b.image);
    CHECK(a.image_width == b.image_width);
    CHECK(a.image_height == b.image_height);
    CHECK(a.type == b.type);
    CHECK(a.tile_offset_x == b.tile_offset_x);
    CHECK(a.tile_offset_y == b.tile_offset_y);
    same_properties(a.properties, b.properties, "tileset");
    REQUIRE(a.tiles.size() == b.tiles.size());
    for (size_t i = 0; i < a.tiles.size(); ++i) {
        const TileInfo &s = a.tiles[i], &t = b.tiles[i];
        INFO("tile " << s.id);
        CHECK(s.id == t.id);
        CHECK(s.type == t.type);
        CHECK(s.has_collision_shapes == t.has_collision_shapes);
        CHECK(s.image == t.image);
        CHECK(s.image_width == t.image_width);
        CHECK(s.image_height == t.image_height);
        same_properties(s.properties, t.properties, "tile");
        REQUIRE(s.animation.size() == t.animation.size());
        for (size_t k = 0; k < s.animation.size(); ++k) {
            CHECK(s.animation[k].tile_id == t.animation[k].tile_id);
            CHECK(s.animation[k].duration_ms == t.animation[k].duration_ms);
        }
        REQUIRE(s.objects.size() == t.objects.size());
        for (size_t k = 0; k < s.objects.size(); ++k) same_object(s.objects[k], t.objects[k]);
    }
}

void same_layer(const TileLayer& a, const TileLayer& b) {
    INFO("layer '" << a.name << "'");
    CHECK(a.name == b.name);
    CHECK(a.origin_col == b.origin_col);
    CHECK(a.origin_row == b.origin_row);
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    CHECK(a.cells == b.cells);
    CHECK(a.solidity == b.solidity);
    CHECK(a.visible == b.visible);
    CHECK(a.opacity == b.opacity);
    CHECK(a.offset_x == b.offset_x);
    CHECK(a.offset_y == b.offset_y);
    same_properties(a.properties, b.properties, "layer");
}

void same_object(const MapObject& a, const MapObject& b) {
    INFO("object " << a.id);
    CHECK(a.id == b.id);
    CHECK(a.name == b.name);
    CHECK(a.type == b.type);
    CHECK(a.x == b.x);
    CHECK(a.y == b.y);
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    CHECK(a.rotation == b.rotation);
    CHECK(a.gid == b.gid);
    CHECK(a.visible == b.visible);
    CHECK(a.shape == b.shape);
    REQUIRE(a.points.size() == b.points.size());
    for (size_t i = 0; i < a.points.size(); ++i) {
        CHECK(a.points[i].x == b.points[i].x);
        CHECK(a.points[i].y == b.points[i].y);
    }
    CHECK(a.text.text == b.text.text);
    CHECK(a.text.font_family == b.text.font_family);
    CHECK(a.text.pixel_size == b.text.pixel_size);
    CHECK(a.text.wrap == b.text.wrap);
    CHECK(a.text.bold == b.text.bold);
    CHECK(a.text.italic == b.text.italic);
    CHECK(a.text.kerning == b.text.kerning);
    CHECK(a.text.color == b.text.color);
    CHECK(a.text.halign == b.text.halign);
    CHECK(a.text.valign == b.text.valign);
    CHECK(a.template_path.empty() == b.template_path.empty());
    same_properties(a.properties, b.properties, "object");
}

void same_tree(const std::vector<LayerInfo>& a, const std::vector<LayerInfo>& b) {
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        const LayerInfo &s = a[i], &t = b[i];
        INFO("layer tree '" << s.name << "'");
        CHECK(s.kind == t.kind);
        CHECK(s.id == t.id);
        CHECK(s.name == t.name);
        CHECK(s.type == t.type);
        CHECK(s.visible == t.visible);
        CHECK(s.opacity == t.opacity);
        CHECK(s.offset_x == t.offset_x);
        CHECK(s.offset_y == t.offset_y);
        CHECK(s.parallax_x == t.parallax_x);
        CHECK(s.parallax_y == t.parallax_y);
        CHECK(s.tint_color == t.tint_color);
        CHECK(s.index == t.index);
        CHECK(s.image == t.image);
        CHECK(s.image_width == t.image_width);
        CHECK(s.image_height == t.image_height);
        CHECK(s.repeat_x == t.repeat_x);
        CHECK(s.repeat_y == t.repeat_y);
        same_properties(s.properties, t.properties, "layer tree");
        same_tree(s.children, t.children);
    }
}

// Field by field: what both readers produce for the same map. (The paths
// differ: the twin lives in json/, and names .tsj tilesets.)
void same_model(const Tilemap& a, const Tilemap& b) {
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    CHECK(a.tile_width == b.tile_width);
    CHECK(a.tile_height == b.tile_height);
    CHECK(a.infinite == b.infinite);
    same_properties(a.properties, b.properties, "map");
    REQUIRE(a.tilesets.size() == b.tilesets.size());
    for (size_t i = 0; i < a.tilesets.size(); ++i) same_tileset(a.tilesets[i], b.tilesets[i]);
    REQUIRE(a.layers.size() == b.layers.size());
    for (size_t i = 0; i < a.layers.size(); ++i) same_layer(a.layers[i], b.layers[i]);
    REQUIRE(a.object_layers.size() == b.object_layers.size());
    for (size_t i = 0; i < a.object_layers.size(); ++i) {
        const ObjectLayer &s = a.object_layers[i], &t = b.object_layers[i];
        CHECK(s.name == t.name);
        same_properties(s.properties, t.properties, "object layer");
        REQUIRE(s.objects.size() == t.objects.size());
        for (size_t j = 0; j < s.objects.size(); ++j) same_object(s.objects[j], t.objects[j]);
    }
    same_tree(a.layer_tree, b.layer_tree);
    CHECK(a.type == b.type);
    CHECK(a.background_color == b.background_color);
    CHECK(a.warnings.size() == b.warnings.size());
    const TileGrid ga = a.solid_grid(), gb = b.solid_grid();
    CHECK(ga.cols() == gb.cols());
    CHECK(ga.rows() == gb.rows());
    for (int64_t r = 0; r < ga.rows(); ++r)
        for (int64_t c = 0; c < ga.cols(); ++c) CHECK(a.cell_kind(c, r) == b.cell_kind(c, r));
}

const Property& prop(const Properties& props, const std::string& name) {
    const Property* p = find_property(props, name);
    REQUIRE_MESSAGE(p, "no property " << name);
    return *p;
}

}  // namespace

TEST_SUITE("tmj") {

TEST_CASE("each JSON twin loads into the model its TMX map loads into") {
    for (const char* name : {"level_xml", "level_csv", "level_base64", "level_zlib", "level_gzip",
                             "level_zstd", "level_zstd_stream", "layers", "tilesets", "infinite",
                             "features/objects", "features/templates", "features/template_rules"}) {
        INFO(name);
        LoadOptions options;
        const Tilemap tmx = load_tilemap(map_path(std::string(name) + ".tmx"), options);
        const Tilemap tmj = load_tilemap(json_path(std::string(name) + ".tmj"), options);
        same_model(tmx, tmj);
    }
}

TEST_CASE("a .tsj tileset reads as its .tsx, animation frames included") {
    const Tilemap m = load_tilemap(json_path("level_csv.tmj"), LoadOptions{});
    REQUIRE(m.tilesets.size() == 1);
    const Tileset& ts = m.tilesets[0];
    CHECK(ts.source == "tilesets/terrain.tsj");
    CHECK(ts.image == "../images/terrain.png");
    CHECK(ts.image_dir == json_path("tilesets"));
    const TileInfo* ladder = ts.tile(6);
    REQUIRE(ladder);
    CHECK(ladder->type == "ladder");
    REQUIRE(ladder->animation.size() == 1);
    CHECK(ladder->animation[0].tile_id == 6);
    CHECK(ladder->animation[0].duration_ms == 100);
}

TEST_CASE("the syntax is told by content: JSON named .tmx, and a TMX map naming a .tsj") {
    const std::string json = R"({"width":1,"height":1,"tilewidth":8,"tileheight":8,
        "layers":[{"type":"tilelayer","name":"a","width":1,"height":1,"data":[0]}]})";
    const Tilemap j = parse_tilemap(json, "looks_like.tmx");
    CHECK(j.width == 1);
    REQUIRE(j.layers.size() == 1);
    const std::string xml = R"(<map width="6" height="4" tilewidth="16" tileheight="16">
 <tileset firstgid="1" source="tilesets/terrain.tsj"/>
 <layer name="ground" width="6" height="4"><data encoding="csv">
0,0,7,0,0,0,0,5,0,0,6,0,1,0,0,0,0,4,1,2,3,3,2,1</data></layer></map>)";
    const Tilemap x = parse_tilemap(xml, json_path("mixed.tmx"));
    REQUIRE(x.tilesets.size() == 1);
    CHECK(x.tilesets[0].tile_count == 8);
    CHECK(x.gid_solid(1));
    CHECK_FALSE(x.gid_solid(5));
}

TEST_CASE("the layer tree keeps groups, kinds, own visibility, opacity, images") {
    const Tilemap m = load_tilemap(json_path("layers.tmj"), LoadOptions{});
    REQUIRE(m.layer_tree.size() == 5);
    CHECK(m.layer_tree[0].kind == LayerKind::Tile);
    CHECK(m.layer_tree[0].name == "background");
    CHECK(m.layer_tree[0].index == 0);
    const LayerInfo& world = m.layer_tree[1];
    CHECK(world.kind == LayerKind::Group);
    CHECK(prop(world.properties, "note").value == "group");
    REQUIRE(world.children.size() == 3);
    CHECK(world.children[0].name == "walls");
    CHECK(world.children[0].index == 1);
    CHECK(world.children[1].kind == LayerKind::Object);
    CHECK(world.children[1].index == 0);
    const LayerInfo& inner = world.children[2];
    CHECK(inner.kind == LayerKind::Group);
    CHECK_FALSE(inner.visible);
    CHECK(inner.opacity == 0.5);
    REQUIRE(inner.children.size() == 1);
    CHECK(inner.children[0].opacity == 0.5);  // its own; the TileLayer has 0.25
    CHECK(m.layers[2].opacity == 0.25);
    CHECK_FALSE(m.layers[2].visible);
    const LayerInfo& sky = m.layer_tree[2];
    CHECK(sky.kind == LayerKind::Image);
    CHECK(sky.image == "images/sky.png");
    CHECK(sky.image_width == 64);
    CHECK(sky.image_height == 24);
    CHECK(m.layer_tree[4].index == 1);
}

TEST_CASE("objects keep their shape, points, text and tile gid") {
    const Tilemap layers = load_tilemap(json_path("layers.tmj"), LoadOptions{});
    CHECK(layers.object_layers[0].objects[0].shape == ObjectShape::Point);
    const auto& e = layers.object_layers[1].objects;
    CHECK(e[0].shape == ObjectShape::Rectangle);
    CHECK(e[2].shape == ObjectShape::Tile);
    CHECK(e[2].gid == (7 | kFlipHorizontal));
    CHECK_FALSE(e[2].visible);
    CHECK(e[3].shape == ObjectShape::Ellipse);
    CHECK(e[4].type == "old");  // "type" before "class", as in TMX

    const Tilemap m = load_tilemap(json_path("objects.tmj"), LoadOptions{});
    const auto& o = m.object_layers[0].objects;
    REQUIRE(o.size() == 6);
    CHECK(o[2].shape == ObjectShape::Polyline);
    CHECK(o[2].rotation == 45);
    REQUIRE(o[2].points.size() == 2);
    CHECK(o[2].points[1].x == 10);
    CHECK(o[2].points[1].y == 5.5);
    CHECK(o[3].shape == ObjectShape::Polygon);
    CHECK(o[3].points.size() == 3);
    CHECK(o[4].shape == ObjectShape::Text);
    CHECK(o[4].text.text == "Hello");
    CHECK(o[4].text.wrap);
    CHECK(o[4].text.bold);
    CHECK_FALSE(o[4].text.italic);
    CHECK(o[4].text.pixel_size == 12);
    CHECK(o[4].text.color == "#ff0000");
    CHECK(o[4].text.halign == "center");
    CHECK(o[4].text.valign == "top");
    CHECK(o[4].text.font_family == "sans-serif");
    // The map's own fields and the layer tree's offsets and class.
    CHECK(m.type == "Level");
    CHECK(m.background_color == "#203040");
    CHECK(m.layer_tree[1].offset_x == 4);
    CHECK(m.layer_tree[1].offset_y == -2);
    CHECK(m.layer_tree[1].type == "Things");
}

TEST_CASE("templates: the template's fields, tile and properties, then the instance's") {
    const Tilemap m = load_tilemap(json_path("objects.tmj"), LoadOptions{});
    const auto& o = m.object_layers[0].objects;
    const MapObject& slime = o[0];
    CHECK(slime.name == "slime");
    CHECK(slime.type == "enemy");
    CHECK(slime.x == 32);
    CHECK(slime.y == 16);
    CHECK(slime.width == 16);
    CHECK(slime.height == 16);
    CHECK(slime.shape == ObjectShape::Tile);
    CHECK(slime.gid == (7 | kFlipHorizontal));  // the map's terrain tileset, firstgid 1
    CHECK(slime.template_path == json_path("templates/slime.tj"));
    REQUIRE(slime.properties.size() == 3);
    CHECK(slime.properties[0].name == "climbable");  // its tile's (terrain's tile 6) come first
    CHECK(prop(slime.properties, "hp").value == "5");  // the instance's
    CHECK(prop(slime.properties, "kind").value == "green");  // the template's
    const MapObject& pit = o[1];
    CHECK(pit.name == "pit");
    CHECK(pit.shape == ObjectShape::Ellipse);
    CHECK(pit.width == 48);
    CHECK(pit.height == 24);
    CHECK(prop(pit.properties, "damage").value == "1");
}

TEST_CASE("properties of every Tiled type") {
    const Tilemap m = load_tilemap(json_path("objects.tmj"), LoadOptions{});
    const Properties& p = m.object_layers[0].objects[5].properties;
    CHECK(prop(p, "owner").type == "object");
    CHECK(prop(p, "owner").value == "1");
    CHECK(prop(p, "icon").type == "file");
    CHECK(prop(p, "icon").value == "icons/star.png");
    CHECK(prop(p, "tint").value == "#80ff0000");
    CHECK(prop(p, "speed").value == "2.5");
    CHECK(prop(p, "brave").value == "true");
    CHECK(prop(p, "mood").property_type == "Mood");
    CHECK(prop(p, "mood").value == "calm");
    CHECK(prop(p, "me").members.empty());  // no project: defaults left out

    const Property& boss = prop(m.properties, "boss");
    CHECK(boss.type == "class");
    CHECK(boss.property_type == "Enemy");
    REQUIRE(boss.members.size() == 2);
    CHECK(boss.members[0].name == "hp");
    CHECK(boss.members[0].type == "int");
    CHECK(boss.members[0].value == "40");
    CHECK(boss.members[1].name == "loot");
    CHECK(boss.members[1].type == "class");
    REQUIRE(boss.members[1].members.size() == 1);
    CHECK(boss.members[1].members[0].value == "7");
    const Property& waves = prop(m.properties, "waves");
    CHECK(waves.type == "list");
    REQUIRE(waves.members.size() == 2);
    CHECK(waves.members[0].name.empty());
    CHECK(waves.members[0].type == "int");
    CHECK(waves.members[0].value == "3");
    CHECK(waves.members[1].type == "string");
    CHECK(waves.members[1].value == "last");
}

TEST_CASE("properties as objects, as Tiled wrote them before 1.2, load as their modern twin's") {
    // old_properties.tmj: "properties" objects with "propertytypes" beside
    // them on the map, layers, tileset and object, and "tileproperties" /
    // "tilepropertytypes" for tiles; some values untyped. Its twin says the
    // same in Tiled 1.2's arrays.
    const Tilemap old = load_tilemap(json_path("old_properties.tmj"));
    const Tilemap modern = load_tilemap(json_path("old_properties_modern.tmj"));
    same_model(old, modern);
    CHECK(prop(old.properties, "gravity").type == "float");
    CHECK(prop(old.properties, "gravity").value == "9.5");
    CHECK(prop(old.properties, "tint").type == "color");
    CHECK(prop(old.properties, "tint").value == "#ff102030");
    CHECK(prop(old.properties, "music").type == "file");
    // Untyped: the type its JSON value has.
    CHECK(prop(old.tilesets[0].properties, "scale").type == "int");
    CHECK(prop(old.layers[0].properties, "name-tag").type == "string");
    CHECK(prop(old.tilesets[0].tiles[1].properties, "label").value == "ledge");
    CHECK(prop(old.object_layers[0].properties, "spawns").type == "float");
    CHECK(prop(old.object_layers[0].properties, "spawns").value == "1.0");
    CHECK(prop(old.object_layers[0].objects[0].properties, "locked").value == "false");
    CHECK(old.tilesets[0].tile_solid(0));  // a tile property still makes it solid
    CHECK(old.cell_kind(0, 0) == modern.cell_kind(0, 0));
    CHECK(parse_error(R"({"orientation": "orthogonal", "width": 1, "height": 1, "tilewidth": 4, "tileheight": 4,
        "properties": {"n": "x"}, "propertytypes": {"n": "vector"}, "layers": []})") ==
          "m.tmj: propertytypes.n is none of string, int, float, bool, color, file, object, class or list");
    CHECK(parse_error(R"({"orientation": "orthogonal", "width": 1, "height": 1, "tilewidth": 4, "tileheight": 4,
        "tilesets": [{"firstgid": 1, "name": "t", "tilewidth": 4, "tileheight": 4, "tileproperties": {"top": {}}}],
        "layers": []})") == "m.tmj: tilesets[0].tileproperties.top is not named by a tile id");
}

TEST_CASE("a project file fills the class members a map leaves at their defaults") {
    LoadOptions options;
    options.project_path = json_path("project.tiled-project");
    const Tilemap m = load_tilemap(json_path("objects.tmj"), options);
    const Property& boss = prop(m.properties, "boss");
    REQUIRE(boss.members.size() == 3);  // in the class's order
    CHECK(boss.members[0].value == "40");
    CHECK(boss.members[1].name == "speed");
    CHECK(boss.members[1].type == "float");
    CHECK(boss.members[1].value == "1.5");
    const Property& loot = boss.members[2];
    CHECK(loot.property_type == "Loot");
    REQUIRE(loot.members.size() == 2);
    CHECK(loot.members[0].value == "7");
    CHECK(loot.members[1].name == "gem");
    CHECK(loot.members[1].type == "color");
    CHECK(loot.members[1].value == "#ff00ff00");
    const Property& me = prop(m.object_layers[0].objects[5].properties, "me");
    REQUIRE(me.members.size() == 3);
    CHECK(me.members[0].value == "10");
    REQUIRE(me.members[2].members.size() == 2);
    CHECK(me.members[2].members[0].value == "1");  // the member's own default
    CHECK(me.members[2].members[1].value == "#ff00ff00");
}

TEST_CASE("the fill is format-neutral: it works on the model, whichever reader made it") {
    Tilemap m = make_tilemap(1, 1, 8, 8, {0}, {});
    Property boss{"boss", "class", "", "Enemy", {{"hp", "int", "2", "", {}}, {"extra", "string", "x", "", {}}}};
    Property list{"l", "list", "", "", {{"", "class", "", "Loot", {}}}};
    m.properties = {boss, list};
    ProjectTypes types;
    types.path = "p.tiled-project";
    types.classes = {{"Enemy", {{"hp", "int", "10", "", {}}, {"speed", "float", "1.5", "", {}}}},
                     {"Loot", {{"gold", "int", "0", "", {}}}}};
    fill_class_defaults(m, types);
    const Property& b = m.properties[0];
    REQUIRE(b.members.size() == 3);
    CHECK(b.members[0].value == "2");
    CHECK(b.members[1].name == "speed");
    CHECK(b.members[2].name == "extra");  // not the class's: kept, after its members
    REQUIRE(m.properties[1].members[0].members.size() == 1);  // list items too
    CHECK(m.properties[1].members[0].members[0].name == "gold");
}

TEST_CASE("project file refusals name the project file") {
    LoadOptions options;
    const TempFile undefined("undefined.tiled-project", R"({"propertyTypes": []})");
    options.project_path = undefined.path;
    CHECK_THROWS_WITH(load_tilemap(json_path("objects.tmj"), options),
                      (undefined.path + ": class 'Enemy' of property 'boss' (the map) is not defined in the project").c_str());
    const TempFile broken("broken.tiled-project", "{\n  \"propertyTypes\": [\n    {\"name\": \"A\", \"type\": \"thing\"}]}");
    options.project_path = broken.path;
    CHECK_THROWS_WITH(load_tilemap(json_path("objects.tmj"), options),
                      (broken.path + ": propertyTypes[0].type is neither \"class\" nor \"enum\" (project file)").c_str());
    const TempFile malformed("malformed.tiled-project", "{\n  \"propertyTypes\": [\n  }");
    options.project_path = malformed.path;
    try {
        load_tilemap(json_path("objects.tmj"), options);
        FAIL("no error");
    } catch (const MapError& e) {
        CHECK(e.file() == malformed.path);
        CHECK(e.line() == 3);
    }
    options.project_path = json_path("no-such.tiled-project");
    try {
        load_tilemap(json_path("objects.tmj"), options);
        FAIL("no error");
    } catch (const MapError& e) {
        CHECK(std::string(e.what()).find("cannot open project file") != std::string::npos);
    }
    // A class that holds itself is refused, not followed forever.
    const TempFile loop("loop.tiled-project", R"({"propertyTypes": [
        {"name": "Enemy", "type": "class", "members": [
          {"name": "next", "type": "class", "propertyType": "Enemy", "value": {}}]}]})");
    options.project_path = loop.path;
    CHECK_THROWS_WITH(load_tilemap(json_path("objects.tmj"), options),
                      (loop.path + ": class 'Enemy' nests itself more than 128 deep (the map)").c_str());
}

TEST_CASE("a gid beyond every tileset: a warning naming map, layer and cell, or strict's error") {
    // The tileset's picture is there (only opened at load, so any bytes do):
    // the one warning is the gid's.
    const TempFile image("beyond.png", "stand-in");
    const TempFile f("beyond.tmj", R"({"width":2,"height":1,"tilewidth":8,"tileheight":8,
        "tilesets":[{"firstgid":1,"name":"t","tilewidth":8,"tileheight":8,"tilecount":2,"columns":2,
                     "image":"ds-tmj-beyond.png","imagewidth":16,"imageheight":8}],
        "layers":[{"type":"tilelayer","name":"a","width":2,"height":1,"data":[1,9]}]})");
    const Tilemap m = load_tilemap(f.path, LoadOptions{});
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == f.path + ": gid 9 at cell (1, 0) of layer 'a' is beyond every tileset; loaded as a missing, non-solid tile");
    CHECK(m.layers[0].raw_gid(1, 0) == 9);
    LoadOptions strict;
    strict.strict = true;
    CHECK_THROWS_WITH(load_tilemap(f.path, strict),
                      (f.path + ": gid 9 at cell (1, 0) of layer 'a' is beyond every tileset").c_str());
}

TEST_CASE("a tileset file that says nothing ({}): a warning naming it, or strict's error") {
    const TempFile ts("nothing.tsj", "{}");
    const TempFile f("nothing.tmj", R"({"width":2,"height":1,"tilewidth":8,"tileheight":8,
        "tilesets":[{"firstgid":1,"source":"ds-tmj-nothing.tsj"}],
        "layers":[{"type":"tilelayer","name":"a","width":2,"height":1,"data":[0,1]}]})");
    const std::string problem =
        "tileset file 'ds-tmj-nothing.tsj' says nothing (no tile size, no image, no tiles): its gids are "
        "missing, non-solid tiles";
    const Tilemap m = load_tilemap(f.path, LoadOptions{});
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == f.path + ": " + problem);
    CHECK_FALSE(m.solid_grid().solid(1, 0));
    LoadOptions strict;
    strict.strict = true;
    CHECK_THROWS_WITH(load_tilemap(f.path, strict), (f.path + ": " + problem).c_str());
}

TEST_CASE("refusals name the file, the JSON path and the reason") {
    const std::string head = R"({"width":2,"height":1,"tilewidth":8,"tileheight":8,)";
    auto layer = [&](const std::string& l) { return head + R"("layers":[)" + l + "]}"; };
    CHECK(parse_error(R"({"width":"4","height":1,"tilewidth":8,"tileheight":8})") ==
          "m.tmj: width is a string, expected a non-negative integer");
    CHECK(parse_error(R"({"width":2,"height":1,"tilewidth":8})") == "m.tmj: the document has no \"tileheight\"");
    CHECK(parse_error("[1, 2]") == "m.tmj: the document is an array, expected an object");
    CHECK(parse_error(R"({"type":"tileset"})") == "m.tmj: type is not \"map\"");
    CHECK(parse_error(layer(R"({"type":"tilelayer","name":"a","width":2,"height":1,"data":[0,-1]})")) ==
          "m.tmj: layers[0].data[1] is the number -1, expected a gid (0 … 4294967295)");
    CHECK(parse_error(layer(R"({"type":"tilelayer","name":"a","width":2,"height":1,"data":[0]})")) ==
          "m.tmj: layer 'a' has 1 cells, expected 2x1 = 2");
    CHECK(parse_error(layer(R"({"type":"tilelayer","name":"a","width":2,"height":1})")) ==
          "m.tmj: layers[0] has no \"data\"");
    CHECK(parse_error(layer(R"({"name":"a"})")) == "m.tmj: layers[0] has no \"type\"");
    CHECK(parse_error(layer(R"({"type":"tilelayer"},{"type":"foo"})")) ==
          "m.tmj: layers[1].type is none of tilelayer, objectgroup, imagelayer or group");
    CHECK(parse_error(layer(R"({"type":"objectgroup","objects":[{"x":"1"}]})")) ==
          "m.tmj: layers[0].objects[0].x is a string, expected a number");
    CHECK(parse_error(head + R"("properties":[{"name":"v","type":"vector","value":1}]})") ==
          "m.tmj: properties[0].type is none of string, int, float, bool, color, file, object, class or list");
    CHECK(parse_error(head + R"("properties":[{"name":"n","type":"int","value":"3"}]})") ==
          "m.tmj: properties[0].value is a string, expected an integer");
    CHECK(parse_error(layer(R"({"type":"tilelayer","name":"a","width":2,"height":1,"encoding":"base64","data":[0,0]})")) ==
          "m.tmj: layers[0].data is an array, expected a string");
    CHECK(parse_error(layer(R"({"type":"tilelayer","name":"a","width":2,"height":1,"compression":"zlib","data":[0,0]})")) ==
          "m.tmj: compression 'zlib' needs base64 encoding");
    CHECK(parse_error(head + R"("infinite":true,"layers":[{"type":"tilelayer","name":"a","chunks":[{"x":0,"y":0,"width":"2","height":1,"data":[0,0]}]}]})") ==
          "m.tmj: layers[0].chunks[0].width is a string, expected a non-negative integer");
    CHECK(parse_error(head + R"("tilesets":[{"firstgid":1,"source":"nope.tsj"}]})", json_path("m.tmj")) ==
          json_path("m.tmj") + ": cannot open tileset '" + json_path("nope.tsj") + "': No such file or directory");
    // A "data" array outside a layer is packed while parsing (json_dom.hpp)
    // but read as the array it is: a class member's raw numbers are refused
    // as any array of non-objects.
    CHECK(parse_error(head + R"("properties":[{"name":"p","type":"class","value":{"data":[1,2]}}]})") ==
          "m.tmj: properties[0].value.data[0] is the number 1, expected an object");
    // Packing stops at the first element that is not a gid; the rest still loads.
    const Tilemap mixed = parse_tilemap(layer(R"({"type":"tilelayer","name":"a","width":2,"height":1,"data":[3,2.0]})"), "m.tmj");
    CHECK(mixed.layers.at(0).raw_gid(0, 0) == 3);
    std::string deep = "{}";
    for (int i = 0; i < 40; ++i) deep = "{\"a\":" + deep + "}";
    CHECK(parse_error(head + R"("properties":[{"name":"p","type":"class","value":)" + deep + "}]}").find(
              " nests properties more than 32 deep") != std::string::npos);
    CHECK(parse_error(std::string(200, '[') + std::string(200, ']')) == "m.tmj: JSON nested more than 128 deep");
}

// What a map names is read, whatever it is: a tileset whose source is a
// secret file must not have the error show the secret, wherever the reader
// stops in it (the parser's "last read", a field's value).
TEST_CASE("a tileset file's contents never reach the error, only its name, line and column") {
    const std::string secret = "SECRET-7f3a";
    const TempFile map("leak.tmj", R"({"width":1,"height":1,"tilewidth":8,"tileheight":8,
        "tilesets":[{"firstgid":1,"source":"ds-tmj-leak.tsj"}]})");
    const std::string tsj = (std::filesystem::temp_directory_path() / "ds-tmj-leak.tsj").string();
    const std::string note = " (tileset of " + map.path + ")";
    const auto error = [&](const std::string& contents) {
        const TempFile ts("leak.tsj", contents);
        try {
            load_tilemap(map.path, LoadOptions{});
        } catch (const MapError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string cases[][2] = {
        {"password = " + secret + "\n", tsj + ":1: malformed XML (XML_ERROR_PARSING_TEXT)" + note},
        {"{\"a\": " + secret + "}",
         tsj + ":1: malformed JSON at column 7: syntax error while parsing value - invalid literal" + note},
        {"{\n  \"token\": \"" + secret + "\n\"}",
         tsj + ":2: malformed JSON at column 24: syntax error while parsing value - invalid string: "
               "control character U+000A (LF) must be escaped to \\u000A or \\n" + note},
        {"{\"type\": \"" + secret + "\"}", tsj + ": type is not \"tileset\"" + note},
        {"{\"tilewidth\": \"" + secret + "\"}", tsj + ": tilewidth is a string, expected a non-negative integer" + note},
        {"{\"transparentcolor\": \"" + secret + "\"}",
         tsj + ": transparentcolor is not a colour (#RRGGBB or #AARRGGBB)" + note},
        {"{\"fillmode\": \"" + secret + "\"}", tsj + ": fillmode is none of stretch, preserve-aspect-fit" + note},
        {"{\"tiles\": [{\"id\": 0, \"properties\": [{\"name\": \"p\", \"value\": 1, \"type\": \"" + secret + "\"}]}]}",
         tsj + ": tiles[0].properties[0].type is none of string, int, float, bool, color, file, object, class or list" +
             note},
    };
    for (const auto& [contents, expected] : cases) {
        INFO(contents);
        const std::string what = error(contents);
        CHECK(what == expected);
        CHECK(what.find(secret) == std::string::npos);
        CHECK(what.find("SECRET") == std::string::npos);
    }
}

TEST_CASE("malformed JSON and bad bytes give the line, never an exception of the parser") {
    try {
        parse_tilemap("{\n  \"width\": 4,\n  oops\n}", "m.tmj");
        FAIL("no error");
    } catch (const MapError& e) {
        CHECK(e.line() == 3);
        CHECK(std::string(e.what()) == "m.tmj:3: malformed JSON at column 3: syntax error while parsing object key - invalid literal");
    }
    try {
        parse_tilemap("{\n\"name\": \"caf\xE9\"}", "m.tmj");
        FAIL("no error");
    } catch (const MapError& e) {
        CHECK(e.line() == 2);
        CHECK(std::string(e.what()).find("ill-formed UTF-8 byte") != std::string::npos);
    }
    CHECK(parse_error("{") == "m.tmj:1: malformed JSON at column 2: syntax error while parsing object key - unexpected end of "
                                "input; expected string literal");
}

}  // TEST_SUITE
