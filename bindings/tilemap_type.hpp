// The tilemap as a Scheme object: a foreign object owning a ds::Tilemap and
// the solid grid physics reads from it.
#pragma once
#include <libguile.h>

#include "tile_grid.hpp"
#include "tilemap/tilemap.hpp"

namespace ds::guile {

struct MapHandle {
    Tilemap map;
    TileGrid grid;
};

void init_tilemap_type();
bool is_tilemap(SCM obj);
// The map behind obj (obj must satisfy is_tilemap).
const MapHandle& tilemap_handle(SCM obj);
// #f → nullptr; a tilemap → its grid; anything else → a Failure.
bool grid_from_scm(SCM obj, const TileGrid*& grid, struct Failure& f);

}  // namespace ds::guile
