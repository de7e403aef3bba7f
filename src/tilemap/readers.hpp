// SPDX-License-Identifier: MIT
// The map readers, one per file syntax, and the dispatch between them. Each
// reader turns one file's text into model pieces and leaves everything after
// parsing to map_build; the dispatchers tell XML from JSON by content, so a
// TMX map may name a .tsj tileset and a JSON map a .tsx.
#pragma once
#include <memory>
#include <string>
#include <string_view>

#include "map_build.hpp"
#include "tilemap.hpp"

namespace ds::build {

enum class Syntax : uint8_t { Xml, Json };
// After a UTF-8 BOM and whitespace: '{' is JSON, anything else XML (whose
// parser then says what is wrong).
Syntax sniff_syntax(std::string_view text);

// A whole map from its text; `file` names it (line 0, no note).
Tilemap read_tmx_map(std::string_view text, const Where& file, LoadState& s);
Tilemap read_json_map(std::string_view text, const Where& file, LoadState& s);

// An external tileset's body into `ts` (whose firstgid and source the map
// set); a source inside it is not followed. Sets ts.image_dir.
void read_tsx_tileset(std::string_view text, const Where& file, LoadState& s, Tileset& ts);
void read_json_tileset(std::string_view text, const Where& file, LoadState& s, Tileset& ts);

// A template file: its object, the fields it writes, and its tileset.
ObjectTemplate read_tx_template(std::string_view text, const Where& file, LoadState& s);
ObjectTemplate read_json_template(std::string_view text, const Where& file, LoadState& s);

// The map at `path`, its text already read and counted.
Tilemap read_map(std::string_view text, const std::string& path, LoadState& s);

// The tileset file `path` (resolved), named at `from` (the map's file and
// line), read within the load's budget into `ts`, by either reader.
void load_tileset_file(const std::string& path, LoadState& s, const Where& from, Tileset& ts);

// The template file `path` (resolved), named at `from`; read once per load
// (cached in s.templates). A template's own template= is not followed
// (Tiled's templates do not nest), so templates cannot loop.
std::shared_ptr<const ObjectTemplate> load_template_file(const std::string& path, LoadState& s,
                                                         const Where& from);

}  // namespace ds::build
