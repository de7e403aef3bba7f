// SPDX-License-Identifier: MIT
// The public entry points of loading a map, and the dispatch that sends each
// file (map, tileset, template) to the reader its content calls for.
#include "tile_shapes.hpp"
#include "image_files.hpp"
#include "map_build.hpp"
#include "project.hpp"
#include "readers.hpp"
#include "tilemap.hpp"

namespace ds {

namespace build {

Syntax sniff_syntax(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    const size_t first = text.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos && (text[first] == '{' || text[first] == '[') ? Syntax::Json
                                                                                 : Syntax::Xml;
}

// A collision shape with no area (none inside its tile) is nothing, and
// one that tries to be a shape and is not (semantics §12) is the whole
// cell, as before shapes were read; neither silently: a warning names the
// file, the tileset, the tile and what is wrong.
void warn_bad_shapes(Tilemap& map) {
    for (const Tileset& ts : map.tilesets)
        for (const TileInfo& t : ts.tiles) {
            if (!t.has_collision_shapes) continue;
            const TileSolidPart part = tile_solid_part(t.objects, ts.tile_width, ts.tile_height, 0);
            if (part.problem.empty()) continue;
            map.warnings.push_back(map.path + ": tileset '" + ts.name + "'" +
                                   (ts.source.empty() ? "" : " (" + ts.source + ")") + ", tile " +
                                   std::to_string(t.id) + ": " + part.problem +
                                   (part.empty ? "; its cells are not solid" : "; its cells are solid whole"));
        }
}

// An atlas whose tilecount is more than its image holds: the tiles past
// the image's end are gids of the map but have no picture. Tiled draws a
// placeholder for them; the engine draws the missing-tile mark, and says
// so once per tileset, naming the first such tile. Judged by the image
// size the tileset declares (the loader does not decode images).
void warn_tiles_past_image(Tilemap& map) {
    for (const Tileset& ts : map.tilesets) {
        if (ts.image.empty() || ts.tile_count <= 0 || ts.image_width <= 0 || ts.image_height <= 0) continue;
        const uint32_t held = tiles_in_image(ts, ts.image_width, ts.image_height, ts.columns);
        if (held >= uint32_t(ts.tile_count)) continue;
        map.warnings.push_back(map.path + ": tileset '" + ts.name + "'" +
                               (ts.source.empty() ? "" : " (" + ts.source + ")") + ": tile " + std::to_string(held) +
                               " and on are past the end of its image '" + ts.image + "' (" +
                               std::to_string(ts.image_width) + "x" + std::to_string(ts.image_height) +
                               " px holds " + std::to_string(held) + " of its " + std::to_string(ts.tile_count) +
                               " tiles); drawn as missing tiles");
    }
}

// A tintcolor without its '#' (map_color.hpp): Tiled reads no colour in
// it and draws the layer untinted, and so does the engine, saying so once
// per layer, as an author who wrote one meant a tint.
void warn_unread_tints(const std::string& path, const std::vector<LayerInfo>& layers,
                       std::vector<std::string>& warnings) {
    for (const LayerInfo& l : layers) {
        if (tint_without_hash(l.tint_color))
            warnings.push_back(path + ": layer '" + l.name + "' has tintcolor '" + l.tint_color +
                               "', which has no '#' and so is no colour (as Tiled reads it); drawn untinted");
        warn_unread_tints(path, l.children, warnings);
    }
}

// A tile object whose gid no tileset holds: Tiled loads such a map and
// shows the tile as missing, and so does the engine, saying so once per
// layer (naming the object and the gid); an error for a strict load, as a
// cell's unknown gid is.
void check_object_gids(Tilemap& map, const LoadState& s) {
    for (const ObjectLayer& layer : map.object_layers) {
        size_t unknown = 0;
        const MapObject* first = nullptr;
        for (const MapObject& o : layer.objects) {
            if (o.shape != ObjectShape::Tile || map.gid_known(o.gid & kGidMask)) continue;
            if (s.options.strict)
                throw MapError(map.path, 0, "tile object " + std::to_string(o.id) + " of layer '" + layer.name +
                                                "' has gid " + std::to_string(o.gid & kGidMask) +
                                                ", beyond every tileset");
            if (unknown++ == 0) first = &o;
        }
        if (first)
            map.warnings.push_back(map.path + ": tile object " + std::to_string(first->id) + " of layer '" +
                                   layer.name + "' has gid " + std::to_string(first->gid & kGidMask) +
                                   ", beyond every tileset" +
                                   (unknown > 1 ? " (" + std::to_string(unknown) + " objects in all)" : "") +
                                   "; drawn as a missing tile");
    }
}

Tilemap read_map(std::string_view text, const std::string& path, LoadState& s) {
    const Where file{path, 0, ""};
    Tilemap map = sniff_syntax(text) == Syntax::Json ? read_json_map(text, file, s)
                                                     : read_tmx_map(text, file, s);
    inherit_tile_classes(map);
    warn_bad_shapes(map);
    warn_tiles_past_image(map);
    warn_unread_tints(map.path, map.layer_tree, map.warnings);
    check_object_gids(map, s);
    check_image_files(s, map);
    for (ObjectLayer& layer : map.object_layers) layer.index = index_objects(map, layer);
    return map;
}

namespace {

std::string named_at(const char* what, const Where& from) {
    return std::string(" (") + what + " of " + from.file +
           (from.line > 0 ? ":" + std::to_string(from.line) : "") + ")";
}

}  // namespace

void load_tileset_file(const std::string& path, LoadState& s, const Where& from, Tileset& ts) {
    std::string error;
    const auto text = read_counted(s, path, error);
    if (!text) from.fail("cannot open tileset '" + path + "': " + error);
    const Where file{path, 0, named_at("tileset", from)};
    if (sniff_syntax(*text) == Syntax::Json)
        read_json_tileset(*text, file, s, ts);
    else
        read_tsx_tileset(*text, file, s, ts);
}

std::shared_ptr<const ObjectTemplate> load_template_file(const std::string& path, LoadState& s,
                                                         const Where& from) {
    if (auto it = s.templates.find(path); it != s.templates.end()) return it->second;
    std::string error;
    const auto text = read_counted(s, path, error);
    if (!text) from.fail("cannot open template '" + path + "': " + error);
    const Where file{path, 0, named_at("template", from)};
    auto tmpl = std::make_shared<ObjectTemplate>(sniff_syntax(*text) == Syntax::Json
                                                     ? read_json_template(*text, file, s)
                                                     : read_tx_template(*text, file, s));
    tmpl->path = path;
    s.templates.emplace(path, tmpl);
    return tmpl;
}

}  // namespace build

Tilemap load_tilemap(const std::string& path, std::vector<uint32_t> solid_gids,
                     const MapLimits& limits) {
    LoadOptions options;
    options.solid_gids = std::move(solid_gids);
    options.limits = limits;
    return load_tilemap(path, options);
}

Tilemap load_tilemap(const std::string& path, const LoadOptions& options) {
    build::check_limits(path, options.limits);
    build::LoadState state(options);
    std::string error;
    const auto text = build::read_counted(state, path, error);
    if (!text) throw MapError(path, 0, "cannot open map: " + error);
    Tilemap map = build::read_map(*text, path, state);
    build::apply_project(state, map);  // the class defaults of LoadOptions::project_path
    return map;
}

Tilemap parse_tilemap(std::string_view text, const std::string& path,
                      std::vector<uint32_t> solid_gids, const MapLimits& limits) {
    build::check_limits(path, limits);
    LoadOptions options;
    options.solid_gids = std::move(solid_gids);
    options.limits = limits;
    build::LoadState state(options);
    build::count_text(state, text, path);
    return build::read_map(text, path, state);
}

}  // namespace ds
