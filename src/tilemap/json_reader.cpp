// Placeholder until the JSON reader lands (issue 22's json part replaces
// this file): JSON maps, tilesets and templates are refused clearly.
#include "readers.hpp"

namespace ds::build {

Tilemap read_json_map(std::string_view, const Where& file, LoadState&) {
    file.fail("JSON maps are not read yet");
}

void read_json_tileset(std::string_view, const Where& file, LoadState&, Tileset&) {
    file.fail("JSON tilesets are not read yet");
}

ObjectTemplate read_json_template(std::string_view, const Where& file, LoadState&) {
    file.fail("JSON templates are not read yet");
}

}  // namespace ds::build
