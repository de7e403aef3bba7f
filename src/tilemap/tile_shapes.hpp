// SPDX-License-Identifier: MIT
// The one place a tile's collision objects (drawn in Tiled's collision
// editor) become the solid part of the cells that show it (semantics §12):
// the whole cell, or one CellShape, turned as the cell's flip bits turn the
// tile.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "../cell_shape.hpp"
#include "tilemap.hpp"

namespace ds {

struct TileSolidPart {
    bool whole = true;   // the whole cell (today's rule), else `shape` or nothing
    bool empty = false;  // no solid at all (whole is false): a shape with no area
    CellShape shape;
    // Why the objects collide as nothing (a rectangle or polygon with no
    // area, or no area inside the tile) or as the whole cell although they
    // tried to be a shape (a polygon that is not convex, or whose part
    // inside has more than kMaxShapeSlants slanted edges on its top or its
    // underside): the loader warns with this text. Empty
    // otherwise.
    std::string problem;
};

// Exactly one rectangle (not rotated) or polygon is read as a shape; any
// other set of objects (none, several, an ellipse, a point, a polyline, a
// text, a tile, a rotated object) is the whole cell. Coordinates are rounded
// to whole px; `flips` are the raw gid's flip bits (kFlipDiagonal first, then
// kFlipHorizontal, then kFlipVertical, as Tiled turns a tile). A rectangle or
// convex polygon is clipped to the tile's square, exactly (it may reach past
// it by at most kMaxShapeReachTiles): its part inside filling the tile is
// the whole cell; with no slanted edge it is a part-tile box; with slanted
// edges all on its top (or all on its underside) it is its bounding box cut
// by each edge's line (one edge: a ramp); with slanted edges on both, a
// floor shape with an underside (a diamond); a polygon that is not convex
// is the whole cell. A shape with no area, or none
// inside the tile, is nothing.
TileSolidPart tile_solid_part(const std::vector<MapObject>& objects, int tile_w, int tile_h, uint32_t flips);

}  // namespace ds
