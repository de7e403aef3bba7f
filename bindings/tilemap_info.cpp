// SPDX-License-Identifier: MIT
#include "tilemap_info.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "failure.hpp"
#include "registry.hpp"
#include "tilemap_type.hpp"

namespace ds::guile {

namespace {

// The loader hands over UTF-8; a byte that is not (a map made some other
// way) becomes U+FFFD instead of a decoding-error.
SCM text(std::string_view s) {
    return scm_from_stringn(s.data(), s.size(), "UTF-8", SCM_FAILED_CONVERSION_QUESTION_MARK);
}

SCM key(const char* name) { return scm_from_utf8_keyword(name); }
SCM key_of(SCM name) { return scm_symbol_to_keyword(scm_string_to_symbol(name)); }
SCM sym(const char* name) { return scm_from_utf8_symbol(name); }
// A type= or class=: a symbol, #f when unset (as objects' #:type always was).
SCM type_symbol(const std::string& type) { return type.empty() ? SCM_BOOL_F : scm_string_to_symbol(text(type)); }

// A keyword plist built front to back: pairs are consed onto a reversed
// list that done() turns around in place. Only an SCM lives in it.
struct PlistBuilder {
    SCM reversed = SCM_EOL;
    void add(SCM k, SCM v) { reversed = scm_cons(v, scm_cons(k, reversed)); }
    void add(const char* k, SCM v) { add(key(k), v); }
    SCM done() { return scm_reverse_x(reversed, SCM_EOL); }
};

// rel as the loader's files name it, resolved against dir (a folder, empty
// for the current one): joined, not normalised, as tile_art opens images.
// #f when rel is empty.
SCM resolved(std::string_view dir, const std::string& rel) {
    if (rel.empty()) return SCM_BOOL_F;
    if (dir.empty() || rel.front() == '/') return text(rel);
    return scm_string_append(scm_list_3(text(dir), scm_from_utf8_string("/"), text(rel)));
}

// The folder of the map file, which image layers' paths are relative to.
std::string_view map_dir(const Tilemap& map) {
    const std::string_view path = map.path;
    const size_t slash = path.rfind('/');
    return slash == std::string_view::npos ? std::string_view{} : path.substr(0, slash);
}

SCM int_value(const std::string& s) {
    long long v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec == std::errc() && end == s.data() + s.size()) return scm_from_int64(v);
    return SCM_BOOL_F;
}

SCM float_value(const std::string& s) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (!s.empty() && end && *end == '\0' && std::isfinite(v)) return tiled_number(v);
    return SCM_BOOL_F;
}

// The keys tilemap-objects writes itself. A custom property spelled like
// one of them gets "property-" in front (again, while that is taken too).
constexpr const char* kObjectKeys[] = {"type",     "name",     "id",       "x",     "y",    "width",
                                       "height",   "layer",    "shape",    "points", "rotation",
                                       "visible?", "gid",      "flips",    "text",  "template"};
constexpr std::string_view kTakenPrefix = "property-";

bool object_key(std::string_view name) {
    for (const char* k : kObjectKeys)
        if (name == k) return true;
    return false;
}

// The keyword a custom property of an object gets. emitted is the plist
// built so far (reversed); only a name that starts with the prefix can
// meet an earlier one there (Tiled's names are unique within an object),
// so only such a name is looked for in it.
SCM object_property_key(const std::string& name, SCM emitted) {
    SCM spelled = text(name);
    if (!object_key(name)) {
        SCM k = key_of(spelled);
        if (!std::string_view(name).starts_with(kTakenPrefix) || scm_is_false(scm_memq(k, emitted))) return k;
    }
    for (;;) {  // a prefixed name is never a built-in key; emitted is finite
        spelled = scm_string_append(scm_list_2(text(kTakenPrefix), spelled));
        SCM k = key_of(spelled);
        if (scm_is_false(scm_memq(k, emitted))) return k;
    }
}

SCM shape_symbol(ObjectShape s) {
    switch (s) {
        case ObjectShape::Rectangle: return sym("rect");
        case ObjectShape::Ellipse: return sym("ellipse");
        case ObjectShape::Capsule: return sym("capsule");
        case ObjectShape::Point: return sym("point");
        case ObjectShape::Polygon: return sym("polygon");
        case ObjectShape::Polyline: return sym("polyline");
        case ObjectShape::Text: return sym("text");
        case ObjectShape::Tile: return sym("tile");
    }
    return sym("rect");
}

SCM points_list(const std::vector<ObjectPoint>& points) {
    SCM all = SCM_EOL;
    for (auto p = points.rbegin(); p != points.rend(); ++p)
        all = scm_cons(scm_cons(tiled_number(p->x), tiled_number(p->y)), all);
    return all;
}

SCM flips_list(uint32_t gid) {
    SCM flips = SCM_EOL;
    if (gid & kFlipDiagonal) flips = scm_cons(sym("diagonal"), flips);
    if (gid & kFlipVertical) flips = scm_cons(sym("vertical"), flips);
    if (gid & kFlipHorizontal) flips = scm_cons(sym("horizontal"), flips);
    return flips;
}

SCM text_plist(const ObjectText& t) {
    PlistBuilder b;
    b.add("text", text(t.text));
    b.add("font-family", text(t.font_family));
    b.add("pixel-size", scm_from_int(t.pixel_size));
    b.add("wrap?", scm_from_bool(t.wrap));
    b.add("bold?", scm_from_bool(t.bold));
    b.add("italic?", scm_from_bool(t.italic));
    b.add("underline?", scm_from_bool(t.underline));
    b.add("strikeout?", scm_from_bool(t.strikeout));
    b.add("kerning?", scm_from_bool(t.kerning));
    b.add("color", text(t.color));
    b.add("halign", scm_string_to_symbol(text(t.halign)));
    b.add("valign", scm_string_to_symbol(text(t.valign)));
    return b.done();
}

SCM object_plist(const MapObject& o, const std::string& layer) {
    PlistBuilder b;
    b.add("type", type_symbol(o.type));
    b.add("name", text(o.name));
    b.add("id", scm_from_int(o.id));
    b.add("x", tiled_number(o.x));
    b.add("y", tiled_number(o.y));
    b.add("width", tiled_number(o.width));
    b.add("height", tiled_number(o.height));
    b.add("layer", text(layer));
    // The rest only where it differs from a plain, upright, visible box.
    if (o.shape != ObjectShape::Rectangle) b.add("shape", shape_symbol(o.shape));
    if (o.shape == ObjectShape::Polygon || o.shape == ObjectShape::Polyline) b.add("points", points_list(o.points));
    if (o.rotation != 0) b.add("rotation", tiled_number(o.rotation));
    if (!o.visible) b.add("visible?", SCM_BOOL_F);
    if (o.shape == ObjectShape::Tile) {
        b.add("gid", scm_from_uint32(o.gid & kGidMask));
        b.add("flips", flips_list(o.gid));
    }
    if (o.shape == ObjectShape::Text) b.add("text", text_plist(o.text));
    if (!o.template_path.empty()) b.add("template", text(o.template_path));
    for (const Property& p : o.properties) b.add(object_property_key(p.name, b.reversed), property_value(p));
    return b.done();
}

// The layer's objects in front of tail.
SCM layer_objects(const ObjectLayer& layer, SCM tail = SCM_EOL) {
    SCM all = tail;
    for (auto o = layer.objects.rbegin(); o != layer.objects.rend(); ++o)
        all = scm_cons(object_plist(*o, layer.name), all);
    return all;
}

SCM kind_symbol(LayerKind k) {
    switch (k) {
        case LayerKind::Tile: return sym("tile");
        case LayerKind::Object: return sym("object");
        case LayerKind::Image: return sym("image");
        case LayerKind::Group: return sym("group");
    }
    return sym("tile");
}

SCM layer_list(const Tilemap& map, const std::vector<LayerInfo>& layers);

SCM layer_plist(const Tilemap& map, const LayerInfo& l) {
    PlistBuilder b;
    b.add("kind", kind_symbol(l.kind));
    b.add("name", text(l.name));
    b.add("id", scm_from_int(l.id));
    b.add("type", type_symbol(l.type));
    b.add("visible?", scm_from_bool(l.visible));
    b.add("opacity", tiled_number(l.opacity));
    b.add("offset-x", tiled_number(l.offset_x));
    b.add("offset-y", tiled_number(l.offset_y));
    b.add("parallax-x", tiled_number(l.parallax_x));
    b.add("parallax-y", tiled_number(l.parallax_y));
    b.add("tint", l.tint_color.empty() ? SCM_BOOL_F : text(l.tint_color));
    b.add("properties", properties_plist(l.properties));
    switch (l.kind) {
        case LayerKind::Tile:
            b.add("layer", scm_from_size_t(l.index));
            break;
        case LayerKind::Object:
            b.add("objects", l.index < map.object_layers.size() ? layer_objects(map.object_layers[l.index]) : SCM_EOL);
            break;
        case LayerKind::Image:
            b.add("image", resolved(map_dir(map), l.image));
            b.add("image-width", scm_from_int(l.image_width));
            b.add("image-height", scm_from_int(l.image_height));
            b.add("repeat-x?", scm_from_bool(l.repeat_x));
            b.add("repeat-y?", scm_from_bool(l.repeat_y));
            break;
        case LayerKind::Group:
            b.add("layers", layer_list(map, l.children));
            break;
    }
    return b.done();
}

SCM layer_list(const Tilemap& map, const std::vector<LayerInfo>& layers) {
    SCM all = SCM_EOL;
    for (auto l = layers.rbegin(); l != layers.rend(); ++l) all = scm_cons(layer_plist(map, *l), all);
    return all;
}

SCM animation_list(const std::vector<AnimationFrame>& frames) {
    SCM all = SCM_EOL;
    for (auto f = frames.rbegin(); f != frames.rend(); ++f)
        all = scm_cons(scm_cons(scm_from_uint32(f->tile_id), scm_from_int(f->duration_ms)), all);
    return all;
}

SCM tile_plist(const Tileset& ts, const TileInfo& t) {
    PlistBuilder b;
    b.add("id", scm_from_uint32(t.id));
    b.add("type", type_symbol(t.type));
    b.add("properties", properties_plist(t.properties));
    if (t.has_collision_shapes) b.add("collision?", SCM_BOOL_T);
    if (!t.image.empty()) {
        b.add("image", resolved(ts.image_dir, t.image));
        b.add("image-width", scm_from_int(t.image_width));
        b.add("image-height", scm_from_int(t.image_height));
    }
    if (!t.animation.empty()) b.add("animation", animation_list(t.animation));
    return b.done();
}

SCM tileset_plist(const Tileset& ts) {
    PlistBuilder b;
    b.add("first-gid", scm_from_uint32(ts.firstgid));
    b.add("name", text(ts.name));
    b.add("type", type_symbol(ts.type));
    b.add("source", ts.source.empty() ? SCM_BOOL_F : text(ts.source));
    b.add("tile-width", scm_from_int(ts.tile_width));
    b.add("tile-height", scm_from_int(ts.tile_height));
    b.add("tile-count", scm_from_int(ts.tile_count));
    b.add("columns", scm_from_int(ts.columns));
    b.add("margin", scm_from_int(ts.margin));
    b.add("spacing", scm_from_int(ts.spacing));
    b.add("image", resolved(ts.image_dir, ts.image));
    if (!ts.image.empty()) {
        b.add("image-width", scm_from_int(ts.image_width));
        b.add("image-height", scm_from_int(ts.image_height));
    }
    b.add("tile-offset", scm_cons(scm_from_int(ts.tile_offset_x), scm_from_int(ts.tile_offset_y)));
    b.add("properties", properties_plist(ts.properties));
    SCM tiles = SCM_EOL;
    for (auto t = ts.tiles.rbegin(); t != ts.tiles.rend(); ++t) tiles = scm_cons(tile_plist(ts, *t), tiles);
    b.add("tiles", tiles);
    return b.done();
}

SCM tilemap_properties(SCM m) {
    return map_accessor(m, "tilemap-properties", [](const Tilemap& t) { return properties_plist(t.properties); });
}

SCM tilemap_layers(SCM m) {
    return map_accessor(m, "tilemap-layers", [](const Tilemap& t) { return layer_list(t, t.layer_tree); });
}

SCM tilemap_tilesets(SCM m) {
    return map_accessor(m, "tilemap-tilesets", [](const Tilemap& t) {
        SCM all = SCM_EOL;
        for (auto ts = t.tilesets.rbegin(); ts != t.tilesets.rend(); ++ts) all = scm_cons(tileset_plist(*ts), all);
        return all;
    });
}

SCM tilemap_warnings(SCM m) {
    return map_accessor(m, "tilemap-warnings", [](const Tilemap& t) {
        SCM all = SCM_EOL;
        for (auto w = t.warnings.rbegin(); w != t.warnings.rend(); ++w) all = scm_cons(text(*w), all);
        return all;
    });
}

SCM tilemap_objects(SCM m) { return map_accessor(m, "tilemap-objects", all_objects); }

// FILE (a path, or #f for none) consed onto FILES.
SCM with_file(SCM file, SCM files) { return scm_is_true(file) ? scm_cons(file, files) : files; }

// Every file a loaded map was read from, consed onto `files` (repeats
// included: the caller drops them), so that live
// editing can watch them: the map, its tileset files, the templates its
// objects (and its tiles' collision objects) came from, and the pictures of
// its tilesets, their tiles and its image layers, each as the loader
// opened it. Built of SCM strings only, with no C++ container to outlive
// a failed allocation.
SCM template_files(const std::vector<MapObject>& objects, SCM files) {
    for (const MapObject& o : objects)
        if (!o.template_path.empty()) files = scm_cons(text(o.template_path), files);
    return files;
}

SCM layer_image_files(const Tilemap& map, const std::vector<LayerInfo>& layers, SCM files) {
    for (const LayerInfo& l : layers) {
        if (l.kind == LayerKind::Image) files = with_file(resolved(map_dir(map), l.image), files);
        if (l.kind == LayerKind::Group) files = layer_image_files(map, l.children, files);
    }
    return files;
}

// The cells of `edited` whose gid differs from `loaded`'s, the map it was
// made from by tilemap-set-tile (the same layers, each of the same extent),
// as (layer col row gid) lists in layer, row, column order: the game's tile
// edits, which a map reload re-applies. Compared here, not by tilemap-gid
// from Scheme, which took 153 ms for one 1000 × 1000 layer. Built back to
// front, so that only SCM values are made, onto the list.
SCM tilemap_edits(SCM loaded, SCM edited) {
    Failure f;
    if (!check_map(loaded, "%tilemap-edits", f) || !check_map(edited, "%tilemap-edits", f)) raise(f);
    const Tilemap& a = tilemap_handle(loaded).map;
    const Tilemap& b = tilemap_handle(edited).map;
    SCM edits = SCM_EOL;
    for (size_t l = std::min(a.layers.size(), b.layers.size()); l-- > 0;) {
        const TileLayer& was = a.layers[l];
        const TileLayer& now = b.layers[l];
        if (was.origin_col != now.origin_col || was.origin_row != now.origin_row || was.width != now.width ||
            was.height != now.height || now.width <= 0)
            continue;  // not one map's edit of the other: nothing to re-apply
        for (size_t i = now.cells.size(); i-- > 0;) {
            const uint32_t gid = now.cells[i];
            if (gid == was.cells[i]) continue;
            const int64_t col = now.origin_col + static_cast<int64_t>(i % static_cast<size_t>(now.width));
            const int64_t row = now.origin_row + static_cast<int64_t>(i / static_cast<size_t>(now.width));
            edits = scm_cons(scm_list_4(scm_from_size_t(l), scm_from_int64(col), scm_from_int64(row),
                                        scm_from_uint32(gid)),
                             edits);
        }
    }
    return edits;
}

SCM tilemap_files(SCM m) {
    return map_accessor(m, "%tilemap-files", [](const Tilemap& t) {
        SCM files = SCM_EOL;
        if (!t.path.empty()) files = scm_cons(text(t.path), files);
        for (const Tileset& ts : t.tilesets) {
            files = with_file(resolved(map_dir(t), ts.source), files);
            files = with_file(resolved(ts.image_dir, ts.image), files);
            for (const TileInfo& tile : ts.tiles) {
                files = with_file(resolved(ts.image_dir, tile.image), files);
                files = template_files(tile.objects, files);
            }
        }
        for (const ObjectLayer& layer : t.object_layers) files = template_files(layer.objects, files);
        files = layer_image_files(t, t.layer_tree, files);
        return scm_reverse_x(files, SCM_EOL);
    });
}

}  // namespace

SCM tiled_number(double v) {
    if (std::trunc(v) == v && std::fabs(v) < kMaxExact) return scm_from_int64(static_cast<int64_t>(v));
    return scm_from_double(v);
}

SCM property_value(const Property& p) {
    if (p.type == "bool") return scm_from_bool(property_is_true(p));
    if (p.type == "class") return properties_plist(p.members);
    if (p.type == "list") {
        SCM items = SCM_EOL;
        for (auto it = p.members.rbegin(); it != p.members.rend(); ++it) items = scm_cons(property_value(*it), items);
        return items;
    }
    // A number Tiled would not write stays the text it is.
    SCM number = SCM_BOOL_F;
    if (p.type == "int" || p.type == "object") number = int_value(p.value);
    else if (p.type == "float") number = float_value(p.value);
    return scm_is_true(number) ? number : text(p.value);
}

SCM properties_plist(const Properties& props) {
    SCM all = SCM_EOL;
    for (auto it = props.rbegin(); it != props.rend(); ++it)
        all = scm_cons(key_of(text(it->name)), scm_cons(property_value(*it), all));
    return all;
}

SCM all_objects(const Tilemap& map) {
    SCM all = SCM_EOL;
    for (auto layer = map.object_layers.rbegin(); layer != map.object_layers.rend(); ++layer)
        all = layer_objects(*layer, all);
    return all;
}

void register_tilemap_info_procedures() {
    define_procedure<1, 0, 0, tilemap_objects>("tilemap-objects",
        "(tilemap-objects tm): the objects of every object layer, in document order, each as an "
        "entity (a keyword list): #:type #:name #:id #:x #:y #:width #:height #:layer, then "
        "#:shape #:points #:rotation #:visible? #:gid #:flips #:text #:template where they apply, "
        "then its custom properties (one spelled like a key above gets property- in front).");
    define_procedure<1, 0, 0, tilemap_properties>("tilemap-properties",
        "(tilemap-properties tm): the map's custom properties, as a keyword list.");
    define_procedure<1, 0, 0, tilemap_layers>("tilemap-layers",
        "(tilemap-layers tm): every layer in file order, each a keyword list with #:kind (tile "
        "object image group), #:name, #:id, #:type, #:visible?, #:opacity, #:offset-x, #:offset-y, "
        "#:parallax-x, #:parallax-y, #:tint, #:properties, and for a tile layer #:layer (its "
        "number for tilemap-gid), an object layer #:objects, an image layer #:image, "
        "#:image-width, #:image-height, #:repeat-x?, #:repeat-y?, a group #:layers.");
    define_procedure<1, 0, 0, tilemap_tilesets>("tilemap-tilesets",
        "(tilemap-tilesets tm): the map's tilesets by first gid, each a keyword list with "
        "#:first-gid, #:name, #:type, #:source, #:tile-width, #:tile-height, #:tile-count, "
        "#:columns, #:margin, #:spacing, #:image (or #f for an image collection), #:image-width, "
        "#:image-height, #:tile-offset (x . y), #:properties and #:tiles (the tiles carrying "
        "something: #:id #:type #:properties, and #:collision? #:image #:animation).");
    define_procedure<2, 0, 0, tilemap_edits>("%tilemap-edits",
        WrapperDoc{"(loaded edited)", "reload-map!", "(downstroke live)"});
    define_procedure<1, 0, 0, tilemap_files>("%tilemap-files",
        WrapperDoc{"(tm)", "load-tilemap", "(downstroke tilemap)"});
    define_procedure<1, 0, 0, tilemap_warnings>("tilemap-warnings",
        "(tilemap-warnings tm): what load-tilemap warned about (gids beyond every tileset), as "
        "a list of strings naming the file, layer and cell.");
}

}  // namespace ds::guile
