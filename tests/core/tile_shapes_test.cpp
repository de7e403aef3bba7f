// SPDX-License-Identifier: MIT
// Tiled collision shapes read as cell shapes (semantics §12): which objects
// make a box, a ramp or the whole cell, how flips turn them, and how the
// loader and make_tilemap refuse or warn about bad ones.
#include <string>
#include <vector>

#include "frame.hpp"
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
    CHECK(whole({polygon({{2, 14}, {14, 14}, {14, 2}, {2, 14}})}) == false);         // a small triangle is a ramp
    MapObject line = polygon({{0, 16}, {16, 0}});
    line.shape = ObjectShape::Polyline;
    CHECK(whole({line}));
}

TEST_CASE("shapes with no area: nothing, with the reason") {
    const ds::TileSolidPart two = ds::tile_solid_part({polygon({{0, 0}, {16, 16}})}, 16, 16, 0);
    CHECK_FALSE(two.whole);
    CHECK(two.empty);
    CHECK(two.problem == "a collision polygon of 2 points (3 at least make a shape)");
    const ds::TileSolidPart flat = ds::tile_solid_part({rect(0, 4, 16, 0)}, 16, 16, 0);
    CHECK_FALSE(flat.whole);
    CHECK(flat.empty);
    CHECK(flat.problem == "a collision rectangle of (16, 0) px has no area");
    const ds::TileSolidPart line = ds::tile_solid_part({polygon({{0, 16}, {8, 8}, {16, 0}})}, 16, 16, 0);
    CHECK(line.empty);
    CHECK(line.problem == "a collision polygon whose points lie on one line has no area");
    // Area only outside the tile, or only along its edge.
    const ds::TileSolidPart past = ds::tile_solid_part({polygon({{16, 16}, {24, 16}, {24, 0}})}, 16, 16, 0);
    CHECK(past.empty);
    CHECK(past.problem == "the part of the collision polygon inside the 16x16 tile has no area");
    const ds::TileSolidPart beside = ds::tile_solid_part({rect(-8, 0, 8, 16)}, 16, 16, 0);
    CHECK(beside.empty);
    CHECK(beside.problem == "the part of the collision rectangle inside the 16x16 tile has no area");
}

TEST_CASE("shapes reaching past the tile: their part inside the cell, exactly") {
    // A 45° ramp drawn 8 px past the right and bottom edges: the same line
    // over the corner of it inside the cell.
    CHECK(shape_of(polygon({{0, 24}, {24, 24}, {24, 0}})) == ramp(8, 8, 16, 16, Cut::Floor, 0, 24, 24, 0));
    // A 2:3 slope whose in-cell part ends at y = 16/3: the box is rounded
    // out to whole px, the cut is the drawn line's.
    CHECK(shape_of(polygon({{0, 16}, {24, 16}, {24, 0}})) == ramp(0, 5, 16, 16, Cut::Floor, 0, 16, 24, 0));
    // Flipped horizontally: the line turns with the tile, then is clipped.
    CHECK(shape_of(polygon({{0, 16}, {24, 16}, {24, 0}}), H) == ramp(0, 5, 16, 16, Cut::Floor, -8, 0, 16, 16));
    // A ceiling ramp reaching above and left of the tile.
    CHECK(shape_of(polygon({{-4, -4}, {16, -4}, {-4, 16}})) == ramp(0, 0, 12, 12, Cut::Ceiling, -4, 16, 16, -4));
    // A box reaching past two sides is the box inside; one covering the
    // cell is the whole cell.
    CHECK(shape_of(rect(4, 8, 20, 12)) == CellShape{4, 8, 16, 16});
    CHECK(whole({rect(-2, -2, 20, 20)}));
    // A ramp whose slant lies wholly outside the tile: a box inside.
    CHECK(shape_of(polygon({{0, 16}, {0, 8}, {20, 8}, {28, 16}})) == CellShape{0, 8, 16, 16});
}

TEST_CASE("shapes reaching past the tile that do not fit: the whole cell, with the reason") {
    const ds::TileSolidPart star = ds::tile_solid_part(
        {polygon({{0, 16}, {8, 12}, {20, 16}, {20, 0}})}, 16, 16, 0);  // not convex
    CHECK(star.whole);
    CHECK(star.problem == "collision point (20, 16) lies outside the 16x16 tile and the polygon is not convex, so "
                          "its part inside is not read");
    const ds::TileSolidPart far = ds::tile_solid_part({polygon({{0, 16}, {33, 16}, {33, 0}})}, 16, 16, 0);
    CHECK(far.whole);
    CHECK(far.problem == "collision point (33, 16) lies more than a tile outside the 16x16 tile");
}

TEST_CASE("convex polygons with several slants on one side: a roof or an underside, left to right") {
    // A peak: two slants meeting at (8, 8); the apex is where they meet.
    CellShape peak = ramp(0, 8, 16, 16, Cut::Floor, 0, 16, 8, 8);
    peak.n_more = 1, peak.more[0] = {8, 8, 16, 16};
    CHECK(shape_of(polygon({{0, 16}, {8, 8}, {16, 16}})) == peak);
    CHECK(peak.apex() == 8);
    CHECK(peak.steepness() == 1.0);
    // A pentagon (a house): walls 8 px high, a roof to (8, 0), drawn either way round.
    CellShape house = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, 0);
    house.n_more = 1, house.more[0] = {8, 0, 16, 8};
    CHECK(shape_of(polygon({{0, 16}, {0, 8}, {8, 0}, {16, 8}, {16, 16}})) == house);
    CHECK(shape_of(polygon({{16, 16}, {16, 8}, {8, 0}, {0, 8}, {0, 16}})) == house);
    // A hill with a flat top and 1:2 and 2:1 sides: apex at the top's left end.
    CellShape hill = ramp(0, 4, 16, 16, Cut::Floor, 0, 12, 4, 4);
    hill.n_more = 1, hill.more[0] = {10, 4, 16, 16};
    CHECK(shape_of(polygon({{0, 16}, {0, 12}, {4, 4}, {10, 4}, {16, 16}})) == hill);
    CHECK(hill.apex() == 4);
    CHECK(hill.steepness() == 2.0);
    // Turned upside down: an underside, its lowest point the apex.
    CellShape under = ramp(0, 0, 16, 16, Cut::Ceiling, 0, 8, 8, 16);
    under.n_more = 1, under.more[0] = {8, 16, 16, 8};
    CHECK(shape_of(polygon({{0, 16}, {0, 8}, {8, 0}, {16, 8}, {16, 16}}), V) == under);
    CHECK(under.apex() == 8);
    // A roof peaking above the tile: its part inside keeps the drawn lines,
    // and the apex is the drawn peak's x.
    CellShape clipped = ramp(0, 0, 16, 16, Cut::Floor, -8, 16, 8, 0);
    clipped.n_more = 1, clipped.more[0] = {8, 0, 24, 16};
    CHECK(shape_of(polygon({{-8, 16}, {8, 0}, {24, 16}})) == clipped);
    CellShape tall = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, -8);
    tall.n_more = 1, tall.more[0] = {8, -8, 16, 8};
    CHECK(shape_of(polygon({{0, 16}, {0, 8}, {8, -8}, {16, 8}, {16, 16}})) == tall);
    CHECK(tall.apex() == 8);
    // Not convex: the whole cell, with the reason.
    const ds::TileSolidPart notch =
        ds::tile_solid_part({polygon({{0, 16}, {16, 16}, {16, 0}, {8, 8}, {0, 8}})}, 16, 16, 0);
    CHECK(notch.whole);
    CHECK(notch.problem == "the collision polygon is not convex");
}

const char* kPolygonTmx = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="4" height="1" tilewidth="16" tileheight="16">
 <tileset firstgid="1" name="roofs" tilewidth="16" tileheight="16" tilecount="3" columns="3">
  <tile id="0"><objectgroup><object id="1" x="0" y="8"><polygon points="0,8 0,0 8,-8 16,0 16,8"/></object></objectgroup></tile>
  <tile id="1"><objectgroup><object id="1" x="8" y="0"><polygon points="0,0 8,8 0,16 -8,8"/></object></objectgroup></tile>
  <tile id="2"><objectgroup><object id="1" x="0" y="0"><polygon points="0,16 16,16 16,0 8,8 0,8"/></object></objectgroup></tile>
 </tileset>
 <layer id="1" name="ground" width="4" height="1">
  <data encoding="csv">1,1073741825,2,3</data>
 </layer>
</map>)";

TEST_CASE("a loaded map: a house, an upside-down one and a diamond collide as drawn; a notch warns") {
    const ds::Tilemap m = ds::parse_tilemap(kPolygonTmx, "roofs.tmx");
    const ds::TileGrid g = m.solid_grid();
    CellShape house = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, 0);
    house.n_more = 1, house.more[0] = {8, 0, 16, 8};
    CellShape under = ramp(0, 0, 16, 16, Cut::Ceiling, 0, 8, 8, 16);
    under.n_more = 1, under.more[0] = {8, 16, 16, 8};
    REQUIRE(g.shape(0, 0) != nullptr);
    CHECK(*g.shape(0, 0) == house);
    REQUIRE(g.shape(1, 0) != nullptr);
    CHECK(*g.shape(1, 0) == under);  // flipped vertically
    CellShape diamond = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, 0);
    diamond.n_more = 1, diamond.more[0] = {8, 0, 16, 8};
    diamond.n_under = 2, diamond.under[0] = {0, 8, 8, 16}, diamond.under[1] = {8, 16, 16, 8};
    REQUIRE(g.shape(2, 0) != nullptr);
    CHECK(*g.shape(2, 0) == diamond);
    CHECK(g.cell(3, 0) == ds::kSolidCell);
    CHECK(m.warnings == std::vector<std::string>{
        "roofs.tmx: tileset 'roofs', tile 2: the collision polygon is not convex; its cells are solid whole"});
}

TEST_CASE("convex polygons slanted on their top and their underside: a floor shape with an underside") {
    // A diamond: top slants to (8, 0), underside slants to (8, 16).
    CellShape diamond = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 8, 0);
    diamond.n_more = 1, diamond.more[0] = {8, 0, 16, 8};
    diamond.n_under = 2, diamond.under[0] = {0, 8, 8, 16}, diamond.under[1] = {8, 16, 16, 8};
    CHECK(shape_of(polygon({{8, 0}, {16, 8}, {8, 16}, {0, 8}})) == diamond);
    CHECK(shape_of(polygon({{0, 8}, {8, 16}, {16, 8}, {8, 0}})) == diamond);
    CHECK(diamond.apex() == 8);
    CHECK(diamond.under_apex() == 8);
    CHECK(diamond.two_sided());
    // A hexagon lying on its side: flat top and bottom, one slant each way
    // on both; its top is highest from x 4, its bottom lowest from x 4.
    CellShape hexagon = ramp(0, 0, 16, 16, Cut::Floor, 0, 8, 4, 0);
    hexagon.n_more = 1, hexagon.more[0] = {12, 0, 16, 8};
    hexagon.n_under = 2, hexagon.under[0] = {0, 8, 4, 16}, hexagon.under[1] = {12, 16, 16, 8};
    CHECK(shape_of(polygon({{4, 0}, {12, 0}, {16, 8}, {12, 16}, {4, 16}, {0, 8}})) == hexagon);
    CHECK(hexagon.apex() == 4);
    CHECK(hexagon.under_apex() == 4);
    // A diamond reaching past every side: its part inside is an octagon
    // whose slants keep the drawn lines.
    CellShape octagon = ramp(0, 0, 16, 16, Cut::Floor, -4, 8, 8, -4);
    octagon.n_more = 1, octagon.more[0] = {8, -4, 20, 8};
    octagon.n_under = 2, octagon.under[0] = {-4, 8, 8, 20}, octagon.under[1] = {8, 20, 20, 8};
    CHECK(shape_of(polygon({{-4, 8}, {8, -4}, {20, 8}, {8, 20}})) == octagon);
    // A 1:2 diamond in a 32 × 16 tile, steepest 0.5 on either side.
    CellShape wide = ramp(0, 0, 32, 16, Cut::Floor, 0, 8, 16, 0);
    wide.n_more = 1, wide.more[0] = {16, 0, 32, 8};
    wide.n_under = 2, wide.under[0] = {0, 8, 16, 16}, wide.under[1] = {16, 16, 32, 8};
    const ds::TileSolidPart flat = ds::tile_solid_part({polygon({{16, 0}, {32, 8}, {16, 16}, {0, 8}})}, 32, 16, 0);
    REQUIRE_FALSE(flat.whole);
    CHECK(flat.shape == wide);
    CHECK(wide.steepness() == 0.5);
    // A one-sided shape has no underside.
    CHECK_FALSE(shape_of(polygon({{0, 16}, {8, 8}, {16, 16}})).two_sided());
}

const char* kDiamondsTmx = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="4" height="1" tilewidth="32" tileheight="32">
 <tileset firstgid="1" name="gems" tilewidth="32" tileheight="32" tilecount="3" columns="3">
  <tile id="0"><objectgroup><object id="1" x="16" y="0"><polygon points="0,0 16,16 0,32 -16,16"/></object></objectgroup></tile>
  <tile id="1"><objectgroup><object id="1" x="8" y="4"><polygon points="0,0 16,0 24,12 16,24 0,24 -8,12"/></object></objectgroup></tile>
  <tile id="2"><objectgroup><object id="1" x="16" y="-8"><polygon points="0,0 24,24 0,48 -24,24"/></object></objectgroup></tile>
 </tileset>
 <layer id="1" name="ground" width="4" height="1">
  <data encoding="csv">1,2,3,2147483651</data>
 </layer>
</map>)";

TEST_CASE("a loaded map of gems: a diamond, a hexagon on its side and one reaching past the tile collide as drawn") {
    const ds::Tilemap m = ds::parse_tilemap(kDiamondsTmx, "gems.tmx");
    const ds::TileGrid g = m.solid_grid();
    CHECK(m.warnings.empty());
    CellShape diamond = ramp(0, 0, 32, 32, Cut::Floor, 0, 16, 16, 0);
    diamond.n_more = 1, diamond.more[0] = {16, 0, 32, 16};
    diamond.n_under = 2, diamond.under[0] = {0, 16, 16, 32}, diamond.under[1] = {16, 32, 32, 16};
    CellShape hexagon = ramp(0, 4, 32, 28, Cut::Floor, 0, 16, 8, 4);
    hexagon.n_more = 1, hexagon.more[0] = {24, 4, 32, 16};
    hexagon.n_under = 2, hexagon.under[0] = {0, 16, 8, 28}, hexagon.under[1] = {24, 28, 32, 16};
    // Reaching 8 px past every side: the octagon inside, its slants the
    // drawn lines; flipped horizontally in the last cell, the same shape,
    // as it is symmetric.
    CellShape past = ramp(0, 0, 32, 32, Cut::Floor, -8, 16, 16, -8);
    past.n_more = 1, past.more[0] = {16, -8, 40, 16};
    past.n_under = 2, past.under[0] = {-8, 16, 16, 40}, past.under[1] = {16, 40, 40, 16};
    REQUIRE(g.shape(0, 0) != nullptr);
    CHECK(*g.shape(0, 0) == diamond);
    REQUIRE(g.shape(1, 0) != nullptr);
    CHECK(*g.shape(1, 0) == hexagon);
    REQUIRE(g.shape(2, 0) != nullptr);
    CHECK(*g.shape(2, 0) == past);
    REQUIRE(g.shape(3, 0) != nullptr);
    CHECK(*g.shape(3, 0) == past);
    CHECK(g.solid_at(16, 1));        // the diamond's top vertex
    CHECK_FALSE(g.solid_at(4, 4));   // above its left slant
    CHECK_FALSE(g.solid_at(4, 28));  // below it
    CHECK(g.solid_at(80, 0));        // the clipped one's flat top, (16, 0) of its cell
    CHECK_FALSE(g.solid_at(65, 2));  // above its top-left slant, y = 8 − 1 there
}

TEST_CASE("a polygon with more slants on one side than a shape may have is the whole cell") {
    // A bowl-shaped hill in a 32 × 64 tile: ten slants on its top.
    const ds::TileSolidPart round = ds::tile_solid_part(
        {polygon({{0, 64}, {1, 48}, {2, 40}, {4, 32}, {8, 28}, {16, 26}, {24, 28}, {28, 32}, {30, 40}, {31, 48},
                  {32, 64}})},
        32, 64, 0);
    CHECK(round.whole);
    CHECK(round.problem == "the collision polygon has 10 slanted edges on its top, more than the 8 a shape may have");
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
    CHECK(g.cell(3, 0) == ds::kEmptyCell);  // a polygon of 2 points: no area, nothing
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
                           "make a shape); its cells are not solid");
}

// Row 2: a zero-area rectangle (col 0) and a 2:3 floor ramp drawn 8 px
// past its tile's right edge (col 1); row 3 a solid floor, top at y = 48.
const char* kReachingTmx = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="3" height="4" tilewidth="16" tileheight="16">
 <tileset firstgid="1" name="past" tilewidth="16" tileheight="16" tilecount="3" columns="3">
  <tile id="0"><properties><property name="solid" type="bool" value="true"/></properties></tile>
  <tile id="1"><objectgroup><object id="1" x="0" y="0"><polygon points="0,16 24,16 24,0"/></object></objectgroup></tile>
  <tile id="2"><objectgroup><object id="1" x="0" y="6" width="16" height="0"/></objectgroup></tile>
 </tileset>
 <layer id="1" name="ground" width="3" height="4">
  <data encoding="csv">0,0,0,
0,0,0,
3,2,0,
1,1,1</data>
 </layer>
</map>)";

// Where a falling 8x8 body whose left edge is at x comes to rest.
ds::Num landed_y(const ds::TileGrid& g, double x) {
    dst::Body b = dst::box(x, 0, 8, 8);
    b.gravity = true;
    for (int f = 0; f < 200 && !b.on_ground; ++f) {
        ds::World world;
        world.bodies = {b};
        world.grid = &g;
        ds::Frame frame;
        frame.step(world, ds::FrameOptions{});
        b = world.bodies[0];
    }
    CHECK(b.on_ground);
    return b.y;
}

TEST_CASE("a loaded shape reaching past its tile collides as its part inside; one with no area as nothing") {
    const ds::Tilemap m = ds::parse_tilemap(kReachingTmx, "past.tmx");
    const ds::TileGrid g = m.solid_grid();
    CHECK(g.cell(0, 2) == ds::kEmptyCell);
    REQUIRE(g.shape(1, 2) != nullptr);
    CHECK(*g.shape(1, 2) == ramp(0, 5, 16, 16, Cut::Floor, 0, 16, 24, 0));
    CHECK(g.cell(2, 2) == ds::kEmptyCell);
    // Over [20, 28) the slant's highest point is at x = 28, tile x 12:
    // 16 − 12·2/3 = 8 below the row's top 32, so the feet rest at 40.
    const ds::Num on_ramp = landed_y(g, 20);
    CHECK(on_ramp.exact);
    CHECK_EXACT(on_ramp, 32);
    // The 8 px drawn past the edge hold nothing: a body over [34, 42)
    // falls to the floor, as one over the zero-area rectangle does.
    CHECK_EXACT(landed_y(g, 34), 40);
    CHECK_EXACT(landed_y(g, 4), 40);
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == "past.tmx: tileset 'past', tile 2: a collision rectangle of (16, 0) px has no area; "
                           "its cells are not solid");
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
