// SPDX-License-Identifier: MIT
// Tiled collision shapes read as cell shapes (semantics §12): which objects
// make a box, a ramp or the whole cell, how flips turn them, and how the
// loader and make_tilemap refuse or warn about bad ones.
#include <string>
#include <vector>

#include "support.hpp"
#include "tilemap/tile_shapes.hpp"
#include "tilemap/tilemap.hpp"

using ds::CellShape;
using ds::Cut;
using ds::MapObject;
using ds::ObjectShape;

namespace {

MapObject polygon(std::vector<std::pair<double, double>> pts, double x = 0, double y = 0) {
    MapObject o;
    o.shape = ObjectShape::Polygon;
    o.x = x, o.y = y;
    for (auto [px, py] : pts) o.points.push_back({px, py});
    return o;
}
MapObject rect(double x, double y, double w, double h) {
    MapObject o;
    o.x = x, o.y = y, o.width = w, o.height = h;
    return o;
}
CellShape ramp(int x0, int y0, int x1, int y1, Cut cut, int ax, int ay, int bx, int by) {
    CellShape s;
    s.x0 = x0, s.y0 = y0, s.x1 = x1, s.y1 = y1, s.cut = cut, s.ax = ax, s.ay = ay, s.bx = bx, s.by = by;
    return s;
}
CellShape shape_of(const MapObject& o, uint32_t flips = 0, int tw = 16, int th = 16) {
    const ds::TileSolidPart p = ds::tile_solid_part({o}, tw, th, flips);
    CHECK_FALSE(p.whole);
    CHECK(p.problem.empty());
    return p.shape;
}
bool whole(const std::vector<MapObject>& objects, uint32_t flips = 0) {
    const ds::TileSolidPart p = ds::tile_solid_part(objects, 16, 16, flips);
    CHECK(p.problem.empty());
    return p.whole;
}

constexpr uint32_t H = ds::kFlipHorizontal, V = ds::kFlipVertical, D = ds::kFlipDiagonal;
const MapObject k45 = polygon({{0, 16}, {16, 16}, {16, 0}});
const MapObject k12lower = polygon({{0, 16}, {16, 16}, {16, 8}});
const MapObject k12upper = polygon({{0, 16}, {16, 16}, {16, 0}, {0, 8}});

}  // namespace

TEST_SUITE("tile-shapes") {

TEST_CASE("rectangles: part-tile boxes; one filling the tile is the whole cell") {
    CHECK(shape_of(rect(0, 8, 16, 8)) == CellShape{0, 8, 16, 16});
    CHECK(shape_of(rect(0, 0, 16, 4)) == CellShape{0, 0, 16, 4});
    CHECK(shape_of(rect(3.4, 2.6, 5, 5)) == CellShape{3, 3, 8, 8});  // rounded to whole px
    CHECK(whole({rect(0, 0, 16, 16)}));
    CHECK(whole({polygon({{0, 0}, {16, 0}, {16, 16}, {0, 16}})}));
}

TEST_CASE("ramps: 45°, 1:2 and 2:1, and their pieces") {
    CHECK(shape_of(k45) == ramp(0, 0, 16, 16, Cut::Floor, 0, 16, 16, 0));
    CHECK(shape_of(k12lower) == ramp(0, 8, 16, 16, Cut::Floor, 0, 16, 16, 8));
    CHECK(shape_of(k12upper) == ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 16, 0));
    CHECK(shape_of(polygon({{0, 16}, {16, 16}, {16, 0}, {8, 0}})) == ramp(0, 0, 16, 16, Cut::Floor, 0, 16, 8, 0));
    CHECK(shape_of(polygon({{8, 16}, {16, 16}, {16, 0}})) == ramp(8, 0, 16, 16, Cut::Floor, 8, 16, 16, 0));
    // The object's own x, y are added; points in any order and direction.
    CHECK(shape_of(polygon({{0, 0}, {8, -8}, {8, 0}}, 8, 16)) == ramp(8, 8, 16, 16, Cut::Floor, 8, 16, 16, 8));
    CHECK(shape_of(polygon({{16, 0}, {16, 16}, {0, 16}})) == shape_of(k45));
    // Repeated and collinear points do not matter.
    CHECK(shape_of(polygon({{0, 16}, {8, 16}, {16, 16}, {16, 16}, {16, 0}})) == shape_of(k45));
    CHECK(shape_of(k12lower).steepness() == 0.5);
}

TEST_CASE("flips turn a ramp as Tiled turns the tile") {
    CHECK(shape_of(k45, H) == ramp(0, 0, 16, 16, Cut::Floor, 0, 0, 16, 16));
    CHECK(shape_of(k45, V) == ramp(0, 0, 16, 16, Cut::Ceiling, 0, 0, 16, 16));
    CHECK(shape_of(k45, H | V) == ramp(0, 0, 16, 16, Cut::Ceiling, 0, 16, 16, 0));
    CHECK(shape_of(k45, D) == shape_of(k45));  // the transposed triangle is itself
    CHECK(shape_of(k45, D | H) == shape_of(k45, H));
    CHECK(shape_of(k12lower, H) == ramp(0, 8, 16, 16, Cut::Floor, 0, 8, 16, 16));
    CHECK(shape_of(k12lower, V) == ramp(0, 0, 16, 8, Cut::Ceiling, 0, 0, 16, 8));
    CHECK(shape_of(k12lower, D) == ramp(8, 0, 16, 16, Cut::Floor, 8, 16, 16, 0));  // 2:1
    CHECK(shape_of(k12lower, D | H) == ramp(0, 0, 8, 16, Cut::Floor, 0, 0, 8, 16));
    CHECK(shape_of(k12lower, D | V) == ramp(8, 0, 16, 16, Cut::Ceiling, 8, 0, 16, 16));
    CHECK(shape_of(k12lower, D | H | V) == ramp(0, 0, 8, 16, Cut::Ceiling, 0, 16, 8, 0));
    CHECK(shape_of(k12upper, H | V) == ramp(0, 0, 16, 16, Cut::Ceiling, 0, 16, 16, 8));
    // A tile that is not square: the diagonal flip scales.
    CHECK(shape_of(polygon({{0, 8}, {32, 8}, {32, 4}}), D, 32, 8) == ramp(16, 0, 32, 8, Cut::Floor, 16, 8, 32, 0));
}

TEST_CASE("anything else is the whole cell, as before shapes were read") {
    MapObject ellipse = rect(0, 0, 16, 16);
    ellipse.shape = ObjectShape::Ellipse;
    CHECK(whole({ellipse}));
    MapObject rotated = rect(0, 8, 16, 8);
    rotated.rotation = 45;
    CHECK(whole({rotated}));
    CHECK(whole({rect(0, 8, 16, 8), rect(0, 0, 4, 4)}));                            // two objects
    CHECK(whole({polygon({{0, 16}, {8, 8}, {16, 16}})}));                            // two slants
    CHECK(whole({polygon({{0, 16}, {16, 16}, {16, 0}, {8, 8}, {0, 8}})}));           // not convex
    CHECK(whole({polygon({{2, 14}, {14, 14}, {14, 2}, {2, 14}})}) == false);         // a small triangle is a ramp
    MapObject line = polygon({{0, 16}, {16, 0}});
    line.shape = ObjectShape::Polyline;
    CHECK(whole({line}));
}

TEST_CASE("bad shapes: the whole cell, with the reason") {
    const ds::TileSolidPart two = ds::tile_solid_part({polygon({{0, 0}, {16, 16}})}, 16, 16, 0);
    CHECK(two.whole);
    CHECK(two.problem == "a collision polygon of 2 points (3 at least make a shape)");
    const ds::TileSolidPart out = ds::tile_solid_part({polygon({{0, 16}, {20, 16}, {20, 0}})}, 16, 16, 0);
    CHECK(out.whole);
    CHECK(out.problem == "collision point (20, 16) lies outside the 16x16 tile");
    const ds::TileSolidPart flat = ds::tile_solid_part({rect(0, 4, 16, 0)}, 16, 16, 0);
    CHECK(flat.whole);
    CHECK(flat.problem == "a collision rectangle of (16, 0) px has no area");
}

const char* kShapedTmx = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="4" height="2" tilewidth="16" tileheight="16">
 <tileset firstgid="1" name="ramps" tilewidth="16" tileheight="16" tilecount="6" columns="6">
  <tile id="0"><properties><property name="solid" type="bool" value="true"/></properties></tile>
  <tile id="1"><objectgroup><object id="1" x="0" y="0"><polygon points="0,16 16,16 16,0"/></object></objectgroup></tile>
  <tile id="2"><objectgroup><object id="1" x="0" y="8" width="16" height="8"/></objectgroup></tile>
  <tile id="3"><properties><property name="one-way" type="bool" value="true"/></properties>
   <objectgroup><object id="1" x="0" y="0"><polygon points="0,16 16,16 16,0"/></object></objectgroup></tile>
  <tile id="4"><objectgroup><object id="1" x="0" y="0"><polygon points="0,16 16,0"/></object></objectgroup></tile>
  <tile id="5"><properties><property name="solid" type="bool" value="true"/></properties>
   <objectgroup><object id="1" x="0" y="8" width="16" height="8"/></objectgroup></tile>
 </tileset>
 <layer id="1" name="ground" width="4" height="2">
  <data encoding="csv">2,2147483650,4,5,
3,6,1,1073741826</data>
 </layer>
</map>)";

TEST_CASE("a loaded map: shapes, flips, one-way shapes, properties, warnings") {
    const ds::Tilemap m = ds::parse_tilemap(kShapedTmx, "shapes.tmx");
    const ds::TileGrid g = m.solid_grid();
    REQUIRE(g.shape(0, 0) != nullptr);
    CHECK(*g.shape(0, 0) == ramp(0, 0, 16, 16, Cut::Floor, 0, 16, 16, 0));
    CHECK(*g.shape(1, 0) == ramp(0, 0, 16, 16, Cut::Floor, 0, 0, 16, 16));  // flipped horizontally
    CellShape one_way = ramp(0, 0, 16, 16, Cut::Floor, 0, 16, 16, 0);
    one_way.one_way = true;
    CHECK(*g.shape(2, 0) == one_way);
    CHECK(g.cell(3, 0) == ds::kSolidCell);  // a bad polygon: the whole cell
    CHECK(*g.shape(0, 1) == CellShape{0, 8, 16, 16});
    CHECK(g.cell(1, 1) == ds::kSolidCell);  // a solid property wins over its shape
    CHECK(g.cell(2, 1) == ds::kSolidCell);
    CHECK(*g.shape(3, 1) == ramp(0, 0, 16, 16, Cut::Ceiling, 0, 0, 16, 16));  // flipped vertically
    CHECK(g.steepest_ramp() == 1.0);
    CHECK(m.cell_solid(0, 0));
    CHECK_FALSE(m.cell_solid(2, 0));
    CHECK(m.cell_one_way(2, 0));
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == "shapes.tmx: tileset 'ramps', tile 4: a collision polygon of 2 points (3 at least "
                           "make a shape); its cells are solid whole");
}

TEST_CASE("a NaN in a collision polygon is refused with the file") {
    std::string text = kShapedTmx;
    text.replace(text.find("0,16 16,0\""), 9, "0,16 nan,0");
    CHECK_THROWS_WITH_AS(ds::parse_tilemap(text, "nan.tmx"), doctest::Contains("nan.tmx"), ds::MapError);
}

TEST_CASE("layers compose: a whole solid cell wins, two different shapes make the whole cell") {
    ds::Tilemap m = ds::make_tilemap(3, 1, 16, 16, {2, 2, 3}, {}, ds::kMaxMapCells, {},
                                     {{2, k45}, {3, rect(0, 8, 16, 8)}});
    ds::TileLayer second = m.layers[0];
    second.cells = std::vector<uint32_t>{0, 2 | H, 3};
    m.layers.push_back(second);
    m.extra_solid_gids = {};
    const ds::TileGrid g = m.solid_grid();
    CHECK(*g.shape(0, 0) == shape_of(k45));
    CHECK(g.cell(1, 0) == ds::kSolidCell);       // two different shapes
    CHECK(*g.shape(2, 0) == CellShape{0, 8, 16, 16});  // the same shape twice
    m.extra_solid_gids = {3};
    CHECK(m.solid_grid().cell(2, 0) == ds::kSolidCell);
}

TEST_CASE("set_tile gives and takes shapes, and the grid's revision changes") {
    ds::Tilemap m = ds::make_tilemap(2, 1, 16, 16, {1, 0}, {1}, ds::kMaxMapCells, {}, {{2, k45}});
    ds::TileGrid g = m.solid_grid();
    CHECK_FALSE(g.has_shapes());
    const uint64_t before = g.revision();
    ds::set_tile(m, g, 0, 1, 0, 2 | V);
    CHECK(*g.shape(1, 0) == shape_of(k45, V));
    CHECK(g.revision() != before);
    ds::set_tile(m, g, 0, 1, 0, 1);
    CHECK(g.cell(1, 0) == ds::kSolidCell);
    CHECK(g.shape(1, 0) == nullptr);
}

TEST_CASE("make_tilemap refuses a bad shape, naming the gid") {
    CHECK_THROWS_WITH_AS(ds::make_tilemap(1, 1, 16, 16, {1}, {}, ds::kMaxMapCells, {},
                                          {{1, polygon({{0, 0}, {1, 1}})}}),
                         "make_tilemap: the shape of gid 1: a collision polygon of 2 points (3 at least make a shape)",
                         std::invalid_argument);
}

}  // TEST_SUITE
