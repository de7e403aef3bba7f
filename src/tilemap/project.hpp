// SPDX-License-Identifier: MIT
// A Tiled project file (.tiled-project, JSON): the custom property types
// its "propertyTypes" define, and the post-parse step that fills in the
// class members a map leaves at their defaults (Tiled writes only the
// members that differ). Knows no map syntax: it works on the model.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tilemap.hpp"

namespace ds {

// A class type: its members with their defaults, in the project's order.
struct PropertyClass {
    std::string name;
    Properties members;
};

struct ProjectTypes {
    std::string path;  // the project file, for messages
    std::vector<PropertyClass> classes;
    std::vector<std::string> enums;  // names only: an enum value is kept as written

    const PropertyClass* find_class(std::string_view name) const;
};

// The project's types from its text; MapError naming `path` (and the line
// when the JSON is malformed) when it is not a project Tiled could have written.
ProjectTypes parse_project(std::string_view text, const std::string& path);

// Every class property of the map (map, layers, objects, tilesets, tiles;
// inside classes and lists too) gets the members it leaves out, with the
// project's defaults, in the class's member order (members the class does
// not define stay, after them); a member whose type the map could not tell
// (JSON writes bare values) takes the type the class gives it. MapError
// naming the project file for a class it does not define, a class nested
// in itself past kMaxJsonDepth, or more than kMaxFilledMembers filled.
void fill_class_defaults(Tilemap& map, const ProjectTypes& types);

namespace build {
struct LoadState;
// When the load's options name a project file: reads it (a regular file,
// within the load's max-bytes) and fills `map`'s class defaults.
void apply_project(LoadState& s, Tilemap& map);
}  // namespace build

}  // namespace ds
