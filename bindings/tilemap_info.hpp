// SPDX-License-Identifier: MIT
// What a loaded map holds beyond its cells, as Scheme values: custom
// properties, objects, the layer tree, tilesets and the loader's warnings
// (docs/tilemaps.org lists every key). Each conversion only reads the
// model and builds Scheme data: no C++ object with a destructor is alive
// while it calls libguile, so an allocation failure may longjmp out of it.
#pragma once
#include <libguile.h>

#include "tilemap/tilemap.hpp"

namespace ds::guile {

// A Tiled number: integral values come back exact, so 48 stays 48.
SCM tiled_number(double v);
// One property's value: string/color/file → string, int/object → exact
// integer, float → number, bool → boolean, class → keyword plist of its
// members, list → list of values.
SCM property_value(const Property& p);
// A keyword plist of properties, in file order.
SCM properties_plist(const Properties& props);
// Every object of every object layer, in document order, as entity plists.
SCM all_objects(const Tilemap& map);

void register_tilemap_info_procedures();

}  // namespace ds::guile
