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
// The "properties" array of `owner`, empty when absent.
Properties read_properties(const Node& owner);

}  // namespace ds::json
