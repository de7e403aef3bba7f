// SPDX-License-Identifier: MIT
// Tiled's JSON custom properties ([{name, type, propertytype, value}]) as
// the model's Property, shared by the map readers and the project file.
// Every Tiled type is read: scalars keep their text (numbers as JSON writes
// them), a class its members (bare JSON values, their type inferred: string,
// bool, int, float, class, list), a list its items ({type, value}).
#pragma once
#include <string>

#include "tilemap.hpp"
#include "json_values.hpp"

namespace ds::json {

// One property or class member definition: `n` is its {type, value, ...}
// object, `depth` how many classes or lists it is inside (at most
// kMaxPropertyDepth, as TMX).
Property read_typed(const Node& n, std::string name, int depth = 0);
// The "properties" of `owner`, empty when absent: an array, or an object
// as before Tiled 1.2 (read_property_object, its types in "propertytypes").
Properties read_properties(const Node& owner);
// Properties as Tiled wrote them in JSON before 1.2, and as Tiled still
// reads them (VariantToMapConverter::toProperties): an object of name →
// value, with `types` (when given) an object of name → Tiled type beside
// it ("propertytypes", or a tileset's "tilepropertytypes" per tile).
Properties read_property_object(const Node& values, const Node* types);

}  // namespace ds::json
