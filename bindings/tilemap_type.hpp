// SPDX-License-Identifier: MIT
// The tilemap as a Scheme object: a foreign object owning a ds::Tilemap and
// the solid grid physics reads from it.
#pragma once
#include <libguile.h>

#include "failure.hpp"
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
// Checks a tilemap argument: false, with a Failure naming proc and the
// value, when obj is not one.
bool check_map(SCM obj, const char* proc, Failure& f);
// An accessor's body: checks obj, then returns get(the map), which only
// reads the map and builds Scheme values.
template <typename Get>
SCM map_accessor(SCM obj, const char* proc, Get get) {
    Failure f;
    if (!check_map(obj, proc, f)) raise(f);
    return get(tilemap_handle(obj).map);
}
// #f → nullptr; a tilemap → its grid; anything else → a Failure.
bool grid_from_scm(SCM obj, const TileGrid*& grid, Failure& f);

// tilemap-cell-shape and tilemap-steepest-ramp (tilemap_shape_procs.cpp).
void register_tilemap_shape_procedures();

}  // namespace ds::guile

