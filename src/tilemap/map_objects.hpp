// SPDX-License-Identifier: MIT
// What a map object is and where a tile object's picture goes: one home for
// the readers (TMX, JSON), the template merge and the renderer.
#pragma once
#include <utility>

#include "tilemap.hpp"

namespace ds {

// A tile object when it has a gid (whatever shape it also names, as Tiled
// draws it), else the shape it was given.
ObjectShape object_kind(uint32_t gid, ObjectShape shape);

// The size a tile's picture has: a collection tile's own, else its tileset's
// tile size. (0, 0) for a gid no tileset holds.
std::pair<double, double> tile_picture_size(const Tilemap& map, uint32_t gid);

// Where a tile object is drawn, in map px, before rotation: the box
// [left, left + width) × [top, top + height), turned by `rotation` degrees
// clockwise about (pivot_x, pivot_y), the object's (x, y). Its size is the
// object's, or its tile's when the object gives none; (x, y) names the box's
// point its tileset's alignment says (bottom-left when unspecified).
struct TileObjectBox {
    double left = 0, top = 0, width = 0, height = 0;
    double pivot_x = 0, pivot_y = 0, rotation = 0;
};
TileObjectBox tile_object_box(const Tilemap& map, const MapObject& object);

}  // namespace ds
