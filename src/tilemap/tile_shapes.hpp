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
    // tried to be a shape (a polygon reaching past the tile that is not
    // convex, or whose part inside is neither a box nor a ramp): the loader
    // warns with this text. Empty otherwise.
    std::string problem;
};

// Exactly one rectangle (not rotated) or polygon is read as a shape; any
// other set of objects (none, several, an ellipse, a point, a polyline, a
// text, a tile, a rotated object) is the whole cell. Coordinates are rounded
// to whole px; `flips` are the raw gid's flip bits (kFlipDiagonal first, then
// kFlipHorizontal, then kFlipVertical, as Tiled turns a tile). A rectangle or
// polygon filling the tile is the whole cell; a polygon that is its bounding
// box cut by one slanted edge (a triangle or trapezoid with a horizontal and
// a vertical side) is a ramp; any other polygon is the whole cell. A
// rectangle or convex polygon reaching past the tile (by at most
// kMaxShapeReachTiles) is clipped to the tile's square, exactly, and its
// part inside is read by the same rule; a shape with no area, or none
// inside the tile, is nothing.
TileSolidPart tile_solid_part(const std::vector<MapObject>& objects, int tile_w, int tile_h, uint32_t flips);

}  // namespace ds
