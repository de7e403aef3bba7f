// SPDX-License-Identifier: MIT
// The JSON syntax: a .tmj map, a .tsj tileset and a .tj template (Tiled's
// JSON map format) read with nlohmann::json into the same model pieces the
// TMX reader makes; what follows parsing (budgets, cell checks, decoding,
// gid checks, templates) is map_build's. Every failure is a MapError naming
// the file, the JSON path and the reason (the line too when the JSON itself
// is malformed); unknown keys are skipped.
#include <algorithm>
#include <charconv>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "json_dom.hpp"
#include "json_properties.hpp"
#include "json_values.hpp"
#include "draw_attrs.hpp"
#include "map_build.hpp"
#include "map_objects.hpp"
#include "readers.hpp"
#include "tilemap.hpp"

namespace ds::build {

namespace {

using json::Json;
using json::Node;
using json::read_properties;

// One JSON file being read: where its messages point and the load's state.
struct JsonFile {
    Where where;
    LoadState* state;
};

// Every JsonError (a path and a reason) becomes a MapError on the file;
// MapErrors from map_build pass as they are.
template <class Fn>
auto guard(const Where& file, Fn&& fn) -> decltype(fn()) {
    try {
        return fn();
    } catch (const json::JsonSyntaxError& e) {
        file.at(e.line).fail(e.what());
    } catch (const json::JsonError& e) {
        file.fail(e.what());
    } catch (const Json::exception& e) {  // none expected: every access is checked first
        file.fail(std::string("unexpected JSON: ") + e.what());
    }
}

// The document's root object, whose "type" (when written) must be `kind`.
Node root_of(const Json& doc, const char* kind) {
    Node root{&doc, ""};
    if (!doc.is_object()) throw json::JsonError("the document is " + json::describe(doc) + ", expected an object");
    if (root.has("type") && root["type"].string() != kind)
        root["type"].fail("is not \"" + std::string(kind) + "\"");  // its text unquoted: json_values.cpp
    return root;
}

// "type" (Tiled ≤ 1.8 and ≥ 1.10) or "class" (1.9), for objects and tiles.
std::string type_or_class(const Node& n) {
    std::string t = json::string_or(n, "type");
    return t.empty() ? json::string_or(n, "class") : t;
}

// --- objects ----------------------------------------------------------------

std::vector<ObjectPoint> read_points(const Node& list) {
    std::vector<ObjectPoint> points;
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node p = list[i];
        p.object();
        points.push_back({json::number_or(p, "x", 0), json::number_or(p, "y", 0)});
    }
    return points;
}

ObjectText read_text(const Node& t) {
    t.object();
    ObjectText text;
    text.text = json::string_or(t, "text");
    text.font_family = json::string_or(t, "fontfamily", text.font_family);
    text.pixel_size = json::int_or(t, "pixelsize", text.pixel_size);
    text.wrap = json::bool_or(t, "wrap", false);
    text.bold = json::bool_or(t, "bold", false);
    text.italic = json::bool_or(t, "italic", false);
    text.underline = json::bool_or(t, "underline", false);
    text.strikeout = json::bool_or(t, "strikeout", false);
    text.kerning = json::bool_or(t, "kerning", true);
    text.color = json::string_or(t, "color", text.color);
    text.halign = json::string_or(t, "halign", text.halign);
    text.valign = json::string_or(t, "valign", text.valign);
    return text;
}

// The shape keys (ellipse, capsule, point, polygon, polyline, text), when one is written.
bool read_shape(const Node& n, MapObject& o) {
    if (n.has("polygon")) {
        o.shape = ObjectShape::Polygon;
        o.points = read_points(n["polygon"]);
    } else if (n.has("polyline")) {
        o.shape = ObjectShape::Polyline;
        o.points = read_points(n["polyline"]);
    } else if (json::bool_or(n, "ellipse", false)) {
        o.shape = ObjectShape::Ellipse;
    } else if (json::bool_or(n, "capsule", false)) {
        o.shape = ObjectShape::Capsule;
    } else if (json::bool_or(n, "point", false)) {
        o.shape = ObjectShape::Point;
    } else if (n.has("text")) {
        o.shape = ObjectShape::Text;
    } else {
        return false;
    }
    return true;
}

// An object and which of its fields the file writes (a template instance
// takes the others from its template).
std::pair<MapObject, ObjectFields> read_object(const Node& n) {
    n.object();
    MapObject o;
    ObjectFields f;
    o.id = json::int_or(n, "id", 0);
    f.rotation = n.has("rotation"), f.visible = n.has("visible");
    f.text = n.has("text");
    o.name = json::string_or(n, "name");
    o.type = type_or_class(n);
    o.x = json::number_or(n, "x", 0);
    o.y = json::number_or(n, "y", 0);
    o.width = json::extent_or(n, "width", 0);
    o.height = json::extent_or(n, "height", 0);
    o.rotation = json::number_or(n, "rotation", 0);
    o.gid = json::uint_or(n, "gid", 0u);
    o.visible = json::bool_or(n, "visible", true);
    f.shape = read_shape(n, o);
    if (f.text) o.text = read_text(n["text"]);
    o.shape = object_kind(o.gid, o.shape);
    o.properties = read_properties(n);
    return {std::move(o), f};
}

// An object of a map's object layer, its template (if any) merged in.
MapObject read_map_object(const JsonFile& f, const Node& n, Tilemap* map) {
    auto [o, fields] = read_object(n);
    if (n.has("template")) {
        const std::string path = resolve_path(f.where.file, n["template"].string());
        const auto tmpl = load_template_file(path, *f.state, f.where);
        merge_template(f.where, *f.state, *tmpl, fields, o, map);
    }
    return o;
}

// --- tilesets ---------------------------------------------------------------

// A size of at most `max` px: image sides, spacing, margin, columns.
int bounded(const Node& n, const char* key, int64_t max) {
    const int v = json::size_or(n, key, 0);
    if (v > max)
        n[key].fail("is " + std::to_string(v) + ", larger than the limit of " + std::to_string(max) + " px");
    return v;
}

std::vector<AnimationFrame> read_animation(const Node& list) {
    std::vector<AnimationFrame> frames;
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node fr = list[i];
        fr.object();
        frames.push_back({json::uint_or(fr, "tileid", std::nullopt), json::size_or(fr, "duration", 0)});
    }
    return frames;
}

TileInfo read_tile(const JsonFile& f, const Node& n, const Tileset& ts) {
    n.object();
    TileInfo t;
    t.id = json::uint_or(n, "id", std::nullopt);
    t.type = type_or_class(n);
    t.properties = read_properties(n);
    // Only an objectgroup holding at least one shape counts as collision.
    if (n.has("objectgroup")) {
        const Node group = n["objectgroup"];
        group.object();
        const Json& objects = json::array_or_empty(group, "objects");
        t.has_collision_shapes = !objects.empty();
        const Node list{&objects, group.path + ".objects"};
        // No map: a template's gid stays as its template has it.
        for (size_t i = 0; i < objects.size(); ++i) t.objects.push_back(read_map_object(f, list[i], nullptr));
        check_shape_points(f.where, ts, t);
    }
    if (n.has("image")) {
        t.image = n["image"].string();
        t.image_width = bounded(n, "imagewidth", kMaxImageSide);
        t.image_height = bounded(n, "imageheight", kMaxImageSide);
    }
    if (n.has("animation")) t.animation = read_animation(n["animation"]);
    return t;
}

// A colour key (map_color.hpp): nullopt when absent, an error naming the key
// and its value when malformed.
std::optional<MapColor> color_or(const Node& n, const char* key) {
    if (!n.has(key)) return std::nullopt;
    const std::string text = n[key].string();
    const auto c = parse_map_color(text);
    if (!c) n[key].fail("is not a colour (#RRGGBB or #AARRGGBB)");  // its text unquoted: json_values.cpp
    return c;
}

// One of a key's named values (`parse` reads them): `fallback` when absent,
// an error listing the known ones when unknown.
template <typename T, typename Parse>
T named_or(const Node& n, const char* key, T fallback, Parse parse, const char* expected) {
    if (!n.has(key)) return fallback;
    const std::string text = n[key].string();
    const std::optional<T> v = parse(std::string_view(text));
    if (!v) n[key].fail("is none of " + std::string(expected));  // its text unquoted: json_values.cpp
    return *v;
}

// Tile properties as Tiled wrote them before 1.2, and as Tiled still reads
// them: "tileproperties" maps each tile id (a decimal key) to its
// properties object, "tilepropertytypes" the same ids to their types.
void read_old_tile_properties(const Node& n, Tileset& ts) {
    const Node all = n["tileproperties"];
    all.object();
    const bool typed = n.has("tilepropertytypes");
    const Node all_types = typed ? n["tilepropertytypes"] : all;
    if (typed) all_types.object();
    for (const auto& [key, value] : all.value->items()) {
        const Node props{&value, all.path + "." + key};
        uint32_t id = 0;
        const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), id);
        if (ec != std::errc() || end != key.data() + key.size()) props.fail("is not named by a tile id");
        Properties read;
        if (typed && all_types.has(key.c_str())) {
            const Node types = all_types[key.c_str()];
            read = json::read_property_object(props, &types);
        } else {
            read = json::read_property_object(props, nullptr);
        }
        auto it = std::find_if(ts.tiles.begin(), ts.tiles.end(), [&](const TileInfo& t) { return t.id == id; });
        if (it == ts.tiles.end()) {
            ts.tiles.push_back({});
            it = ts.tiles.end() - 1;
            it->id = id;
        }
        it->properties = std::move(read);
    }
}

// What a tileset says of itself, embedded or in a .tsj.
void read_tileset_body(const JsonFile& f, const Node& n, Tileset& ts) {
    ts.name = json::string_or(n, "name");
    ts.type = json::string_or(n, "class");
    ts.tile_width = json::size_or(n, "tilewidth", 0);
    ts.tile_height = json::size_or(n, "tileheight", 0);
    check_tile_size(f.where, ts);
    ts.tile_count = json::size_or(n, "tilecount", 0);
    ts.columns = bounded(n, "columns", kMaxImageSide);
    ts.spacing = bounded(n, "spacing", kMaxImageSide);
    ts.margin = bounded(n, "margin", kMaxImageSide);
    ts.image = json::string_or(n, "image");
    if (!ts.image.empty()) {
        ts.image_width = bounded(n, "imagewidth", kMaxImageSide);
        ts.image_height = bounded(n, "imageheight", kMaxImageSide);
    }
    ts.trans = color_or(n, "transparentcolor");
    ts.object_alignment = named_or(n, "objectalignment", ObjectAlignment::Unspecified, parse_object_alignment,
                                   "unspecified, topleft, top, topright, left, center, right, "
                                   "bottomleft, bottom, bottomright");
    ts.render_size = named_or(n, "tilerendersize", TileRenderSize::Tile, parse_tile_render_size, "tile, grid");
    ts.fill_mode = named_or(n, "fillmode", FillMode::Stretch, parse_fill_mode, "stretch, preserve-aspect-fit");
    if (n.has("tileoffset")) {
        const Node off = n["tileoffset"];
        off.object();
        ts.tile_offset_x = json::int_or(off, "x", 0);
        ts.tile_offset_y = json::int_or(off, "y", 0);
    }
    ts.properties = read_properties(n);
    if (n.has("tiles")) {
        const Node tiles = n["tiles"];
        for (size_t i = 0; i < tiles.array().size(); ++i) ts.tiles.push_back(read_tile(f, tiles[i], ts));
    }
    if (n.has("tileproperties")) read_old_tile_properties(n, ts);
    sort_tiles(ts);
}

// A map's tileset: embedded, or naming a tileset file (of either syntax)
// whose own "source" is not followed, so tilesets cannot refer to one
// another in a cycle.
Tileset read_tileset(const JsonFile& f, const Node& n) {
    n.object();
    Tileset ts;
    ts.firstgid = json::uint_or(n, "firstgid", std::nullopt);
    check_firstgid(f.where, ts.firstgid, std::to_string(ts.firstgid));
    ts.source = json::string_or(n, "source");
    if (ts.source.empty()) {
        read_tileset_body(f, n, ts);
        ts.image_dir = std::filesystem::path(f.where.file).parent_path().string();
    } else {
        load_tileset_file(resolve_path(f.where.file, ts.source), *f.state, f.where, ts);
    }
    check_gid_range(f.where, ts);
    return ts;
}

void read_tilesets(const JsonFile& f, const Node& root, Tilemap& map) {
    std::vector<std::pair<Tileset, int>> found;  // JSON has no lines: all 0
    if (root.has("tilesets")) {
        const Node list = root["tilesets"];
        for (size_t i = 0; i < list.array().size(); ++i) found.emplace_back(read_tileset(f, list[i]), 0);
    }
    add_tilesets(f.where, *f.state, std::move(found), map);
}

// --- tile data --------------------------------------------------------------

// "encoding": "csv" (the default) holds an array of gids, "base64" a string.
CellEncoding read_encoding(const JsonFile& f, const Node& layer) {
    const std::string enc = json::string_or(layer, "encoding", "csv");
    const std::string comp = json::string_or(layer, "compression");
    if (enc == "csv") return cell_encoding(f.where, false, "", comp);
    return cell_encoding(f.where, true, enc, comp);
}

// The w×h gids of a layer's or chunk's "data" (at most one past the
// expected count are taken from an array).
std::vector<uint32_t> node_cells(const JsonFile& f, const Node& owner, CellEncoding enc, int w,
                                 int h, const std::string& what) {
    if (!owner.has("data")) owner.fail("has no \"data\"");
    const Node data = owner["data"];
    std::vector<uint32_t> gids;
    std::string text;
    CellData cells{enc, {}, &gids};
    if (enc.kind == CellEncoding::Kind::Array && json::is_packed_gids(*data.value)) {
        gids = json::packed_gids(*data.value, max_array_gids(w, h));  // every element a gid
    } else if (enc.kind == CellEncoding::Kind::Array) {
        const size_t max = max_array_gids(w, h);
        const auto& items = data.array();
        gids.reserve(std::min(items.size(), max));
        for (size_t i = 0; i < items.size() && gids.size() < max; ++i) {
            // A gid is read straight from the array; only a bad one pays for
            // the node (and the path string) its message needs.
            if (items[i].is_number_unsigned() && items[i].get<uint64_t>() <= UINT32_MAX)
                gids.push_back(static_cast<uint32_t>(items[i].get<uint64_t>()));
            else
                gids.push_back(static_cast<uint32_t>(data[i].integer_in(0, UINT32_MAX, "a gid (0 … 4294967295)")));
        }
    } else {
        text = data.string();
        cells.text = text;
    }
    return decode_cells(f.where, *f.state, cells, w, h, what);
}

std::vector<ChunkHead> chunk_heads(const Node& layer) {
    std::vector<ChunkHead> heads;
    const Node list = layer["chunks"];
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node c = list[i];
        c.object();
        heads.push_back({json::int_or(c, "x", std::nullopt), json::int_or(c, "y", std::nullopt),
                         json::size_or(c, "width", std::nullopt), json::size_or(c, "height", std::nullopt),
                         0, i});
    }
    return heads;
}

std::string layer_label(const Node& n) { return json::string_or(n, "name"); }

ChunkSpan layer_chunk_span(const JsonFile& f, const Node& n, const Tilemap& map) {
    if (!n.has("chunks")) n.fail("(layer '" + layer_label(n) + "' of an infinite map) has no \"chunks\"");
    return chunk_span(f.where, *f.state, map, chunk_heads(n), layer_label(n));
}

std::pair<int, int> layer_size(const JsonFile& f, const Node& n, const Tilemap& map) {
    return finite_layer_size(f.where, map, json::size_or(n, "width", map.width),
                             json::size_or(n, "height", map.height), layer_label(n));
}

void read_chunks(const JsonFile& f, const Node& n, CellEncoding enc, Tilemap& map, TileLayer& l,
                 UnknownGids& unknown) {
    const ChunkSpan span = layer_chunk_span(f, n, map);
    std::vector<uint32_t> block = start_chunked_layer(span, l);
    for (const ChunkHead& ch : span.heads) {
        const std::vector<uint32_t> cells =
            node_cells(f, n["chunks"][ch.index], enc, ch.w, ch.h, chunk_name(ch.x, ch.y, l.name));
        check_gids(f.where, *f.state, map, cells, ch.w, ch.x, ch.y, l.name, unknown);
        paste_chunk(span, ch, cells, l, block);
    }
    l.cells = block;
}

// --- layers -----------------------------------------------------------------

LayerKind layer_kind(const Node& n) {
    if (!n.has("type")) n.fail("has no \"type\"");
    const std::string t = n["type"].string();
    if (t == "tilelayer") return LayerKind::Tile;
    if (t == "objectgroup") return LayerKind::Object;
    if (t == "imagelayer") return LayerKind::Image;
    if (t == "group") return LayerKind::Group;
    n["type"].fail("is none of tilelayer, objectgroup, imagelayer or group");
}

// What a layer says of itself, whatever its kind.
LayerInfo read_layer_info(const Node& n) {
    n.object();
    LayerInfo info;
    info.kind = layer_kind(n);
    info.id = json::int_or(n, "id", 0);
    info.name = json::string_or(n, "name");
    info.type = json::string_or(n, "class");
    info.visible = json::bool_or(n, "visible", true);
    info.opacity = json::number_or(n, "opacity", 1.0);
    info.offset_x = json::number_or(n, "offsetx", 0);
    info.offset_y = json::number_or(n, "offsety", 0);
    info.parallax_x = json::number_or(n, "parallaxx", 1);
    info.parallax_y = json::number_or(n, "parallaxy", 1);
    info.tint_color = json::string_or(n, "tintcolor");
    if (!tint_without_hash(info.tint_color)) info.tint = color_or(n, "tintcolor");  // else untinted: load.cpp warns
    info.properties = read_properties(n);
    if (info.kind == LayerKind::Image) {
        info.image = json::string_or(n, "image");
        info.image_width = bounded(n, "imagewidth", kMaxImageSide);
        info.image_height = bounded(n, "imageheight", kMaxImageSide);
        info.repeat_x = json::bool_or(n, "repeatx", false);
        info.repeat_y = json::bool_or(n, "repeaty", false);
        info.image_trans = color_or(n, "transparentcolor");
    }
    return info;
}

void read_tile_layer(const JsonFile& f, const Node& n, const GroupState& g, LayerInfo& info,
                     Tilemap& map) {
    const CellEncoding enc = read_encoding(f, n);
    add_tile_layer(f.where, g, info, map, [&](TileLayer& l, UnknownGids& unknown) {
        if (map.infinite) return read_chunks(f, n, enc, map, l, unknown);
        std::tie(l.width, l.height) = layer_size(f, n, map);
        const std::vector<uint32_t> cells =
            node_cells(f, n, enc, l.width, l.height, "layer '" + l.name + "'");
        check_gids(f.where, *f.state, map, cells, l.width, 0, 0, l.name, unknown);
        l.cells = cells;
    });
}

void read_object_layer(const JsonFile& f, const Node& n, LayerInfo& info, Tilemap& map) {
    ObjectLayer l;
    l.name = info.name;
    l.properties = info.properties;
    l.top_down = named_or(n, "draworder", true, parse_draw_order, "index, topdown");
    if (n.has("objects")) {
        const Node objects = n["objects"];
        for (size_t i = 0; i < objects.array().size(); ++i)
            l.objects.push_back(read_map_object(f, objects[i], &map));
    }
    info.index = map.object_layers.size();
    map.object_layers.push_back(std::move(l));
}

// Each layer of `parent` with fn(layer node), descending into groups (fn
// sees them too) at most kMaxGroupDepth deep.
template <class Fn>
void walk_layers(const JsonFile& f, const Node& parent, int depth, Fn&& fn) {
    if (!parent.has("layers")) return;
    const Node list = parent["layers"];
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node c = list[i];
        c.object();
        fn(c);
        if (layer_kind(c) != LayerKind::Group) continue;
        check_group_depth(f.where, depth);
        walk_layers(f, c, depth + 1, fn);
    }
}

// The whole map's tile-layer cells against max-cells, before any layer is
// decoded or allocated.
void check_cell_total(const JsonFile& f, const Node& root, const Tilemap& map) {
    walk_layers(f, root, 0, [&](const Node& c) {
        if (layer_kind(c) != LayerKind::Tile) return;
        int64_t cells = 0;
        if (map.infinite) {
            cells = layer_chunk_span(f, c, map).cost();
        } else {
            const auto [w, h] = layer_size(f, c, map);
            cells = int64_t{w} * h;
        }
        take_layer_cells(f.where, *f.state, cells, layer_label(c));
    });
}

// Every layer in file order into the tree; tile and object layers also
// into the map's flat lists.
void read_layers(const JsonFile& f, const Node& parent, const GroupState& g, Tilemap& map,
                 std::vector<LayerInfo>& tree) {
    if (!parent.has("layers")) return;
    const Node list = parent["layers"];
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node c = list[i];
        LayerInfo info = read_layer_info(c);
        if (info.kind == LayerKind::Tile)
            read_tile_layer(f, c, g, info, map);
        else if (info.kind == LayerKind::Object)
            read_object_layer(f, c, info, map);
        else if (info.kind == LayerKind::Group)
            read_layers(f, c, g.inside(info), map, info.children);  // depth checked already
        tree.push_back(std::move(info));
    }
}

void read_map_header(const JsonFile& f, const Node& root, Tilemap& map) {
    const std::string orientation = json::string_or(root, "orientation", "orthogonal");
    map.width = json::size_or(root, "width", std::nullopt);
    map.height = json::size_or(root, "height", std::nullopt);
    map.tile_width = json::int_or(root, "tilewidth", std::nullopt);
    map.tile_height = json::int_or(root, "tileheight", std::nullopt);
    map.infinite = json::bool_or(root, "infinite", false);
    check_map_header(f.where, *f.state, map, orientation);
    map.type = json::string_or(root, "class");
    map.background_color = json::string_or(root, "backgroundcolor");
    map.background = color_or(root, "backgroundcolor");
    map.parallax_origin_x = json::number_or(root, "parallaxoriginx", 0);
    map.parallax_origin_y = json::number_or(root, "parallaxoriginy", 0);
    map.render_order = named_or(root, "renderorder", RenderOrder::RightDown, parse_render_order,
                                "right-down, right-up, left-down, left-up");
    map.properties = read_properties(root);
}

}  // namespace

Tilemap read_json_map(std::string_view text, const Where& file, LoadState& s) {
    return guard(file, [&] {
        const Json doc = json::parse(text, kMaxJsonDepth);
        const Node root = root_of(doc, "map");
        const JsonFile f{file, &s};
        Tilemap map;
        map.path = file.file;
        map.extra_solid_gids = s.options.solid_gids;
        read_map_header(f, root, map);
        check_cell_total(f, root, map);
        // Tilesets first, so layers can check their gids.
        read_tilesets(f, root, map);
        read_layers(f, root, {}, map, map.layer_tree);
        if (map.infinite) fit_infinite_bounds(file, s, map);
        return map;
    });
}

void read_json_tileset(std::string_view text, const Where& file, LoadState& s, Tileset& ts) {
    guard(file, [&] {
        const Json doc = json::parse(text, kMaxJsonDepth);
        read_tileset_body({file, &s}, root_of(doc, "tileset"), ts);
        ts.image_dir = std::filesystem::path(file.file).parent_path().string();
    });
}

ObjectTemplate read_json_template(std::string_view text, const Where& file, LoadState& s) {
    return guard(file, [&] {
        const Json doc = json::parse(text, kMaxJsonDepth);
        const Node root = root_of(doc, "template");
        (void)s;
        if (!root.has("object")) root.fail("has no \"object\"");
        ObjectTemplate t;
        t.object = read_object(root["object"]).first;
        if (root.has("tileset")) {
            const Node ts = root["tileset"];
            ts.object();
            t.tileset_firstgid = json::uint_or(ts, "firstgid", std::nullopt);
            check_firstgid(file, t.tileset_firstgid, std::to_string(t.tileset_firstgid));
            if (!ts.has("source")) ts.fail("has no \"source\"");
            t.tileset_path = resolve_path(file.file, ts["source"].string());
        }
        return t;
    });
}

}  // namespace ds::build
