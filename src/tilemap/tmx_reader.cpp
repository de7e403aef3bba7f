// SPDX-License-Identifier: MIT
// The TMX syntax: a .tmx map, a .tsx tileset and a .tx template read with
// tinyxml2 into model pieces; what follows parsing (budgets, cell checks,
// decoding, gid checks, templates) is map_build's. Every failure is a
// MapError naming the file and the line of the offending element; unknown
// elements and attributes are skipped.
#include <tinyxml2.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include "draw_attrs.hpp"
#include "map_build.hpp"
#include "map_objects.hpp"
#include "readers.hpp"
#include "tilemap.hpp"
#include "utf8.hpp"
#include "xml_encoding.hpp"

namespace ds::build {

namespace {

using tinyxml2::XMLElement;

// One XML file being read.
struct XmlFile {
    XmlFile(const Where& w, LoadState& s) : where(w), state(&s) {}

    Where where;
    LoadState* state;  // shared by the map, its tilesets and templates
    tinyxml2::XMLDocument doc;

    Where at(const XMLElement* e) const { return where.at(e ? e->GetLineNum() : 0); }
    [[noreturn]] void fail(const XMLElement* e, const std::string& message) const {
        at(e).fail(message);
    }
};

std::string tag(const XMLElement* e) { return std::string("<") + e->Name() + ">"; }

// tinyxml2's ErrorStr repeats the id and line; keep only its detail.
std::string xml_error(const tinyxml2::XMLDocument& doc) {
    std::string message = std::string("malformed XML (") + doc.ErrorName() + ")";
    const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
    const size_t at = full.find("Line number=");
    const size_t colon = at == std::string::npos ? at : full.find(": ", at);
    if (colon != std::string::npos) message += ": " + full.substr(colon + 2);
    return message;
}

// The text in UTF-8 first (xml_encoding.hpp), so every string read from it
// and every message quoting it is valid UTF-8; tinyxml2 copies it.
void parse_xml(XmlFile& f, std::string_view raw) {
    std::optional<std::string> transcoded;
    try {
        transcoded = tmx::xml_text_as_utf8(raw);
    } catch (const tmx::EncodingError& e) {
        f.where.at(e.line()).fail(e.what());
    }
    const std::string_view text = transcoded ? std::string_view(*transcoded) : raw;
    if (f.doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
        f.where.at(f.doc.ErrorLineNum()).fail(xml_error(f.doc));
}

// The root element, which must be <name>.
const XMLElement* root_named(const XmlFile& f, const char* name) {
    const XMLElement* root = f.doc.RootElement();
    if (!root) f.fail(root, std::string("no <") + name + "> element");
    if (std::strcmp(root->Name(), name) != 0)
        f.fail(root, "root element is " + tag(root) + ", expected <" + name + ">");
    return root;
}

// --- attributes -------------------------------------------------------------

std::string str_attr(const XMLElement* e, const char* name, const char* fallback = "") {
    const char* v = e->Attribute(name);
    return v ? v : fallback;
}

// tinyxml2's Query*Attribute use sscanf, which accepts "12abc" and wraps
// "-1" into an unsigned: a strict parse of the whole value instead.
template <class T>
std::optional<T> parse_number(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    T v{};
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(v)) return std::nullopt;
    return v;
}

template <class T>
T number_attr(const XmlFile& f, const XMLElement* e, const char* name, std::optional<T> fallback) {
    const char* v = e->Attribute(name);
    if (!v) {
        if (fallback) return *fallback;
        f.fail(e, tag(e) + " has no " + name + " attribute");
    }
    if (auto n = parse_number<T>(v)) return *n;
    const char* kind = std::is_floating_point_v<T> ? "a number"
                       : std::is_signed_v<T>       ? "an integer"
                                                   : "a non-negative integer";
    f.fail(e, tag(e) + " attribute " + name + "='" + v + "' is not " + kind);
}

int int_attr(const XmlFile& f, const XMLElement* e, const char* name, std::optional<int> fallback) {
    return number_attr<int>(f, e, name, fallback);
}

// Sizes and counts: an integer that must not be negative.
int size_attr(const XmlFile& f, const XMLElement* e, const char* name,
              std::optional<int> fallback) {
    const int v = int_attr(f, e, name, fallback);
    if (v < 0)
        f.fail(e, tag(e) + " attribute " + name + "='" + str_attr(e, name) + "' is negative");
    return v;
}

double double_attr(const XmlFile& f, const XMLElement* e, const char* name, double fallback) {
    return number_attr<double>(f, e, name, fallback);
}

// An object's width or height: a number that must not be negative (Tiled
// never writes one; a box that reaches back past its own corner has no
// meaning for drawing, indexing or a game's spawn rectangles).
double extent_attr(const XmlFile& f, const XMLElement* e, const char* name) {
    const double v = double_attr(f, e, name, 0);
    if (v < 0) f.fail(e, tag(e) + " attribute " + name + "='" + str_attr(e, name) + "' is negative");
    return v;
}

uint32_t uint_attr(const XmlFile& f, const XMLElement* e, const char* name,
                   std::optional<uint32_t> fallback) {
    return number_attr<uint32_t>(f, e, name, fallback);
}

// Tiled writes visible="0"/"1"; true/false is accepted as well.
bool flag_attr(const XmlFile& f, const XMLElement* e, const char* name, bool fallback) {
    const char* v = e->Attribute(name);
    if (!v) return fallback;
    const std::string s = v;
    if (s == "1" || s == "true") return true;
    if (s == "0" || s == "false") return false;
    f.fail(e, tag(e) + " attribute " + name + "='" + s + "' is not 0 or 1");
}

// type= (Tiled ≤ 1.8 and ≥ 1.10) or class= (1.9).
std::string type_or_class(const XMLElement* e) {
    const char* t = e->Attribute("type");
    return t && *t ? t : str_attr(e, "class");
}

// Children named `name`, in document order.
template <class Fn>
void each_child(const XMLElement* parent, const char* name, Fn fn) {
    for (const XMLElement* c = parent->FirstChildElement(name); c; c = c->NextSiblingElement(name))
        fn(c);
}

Property read_property(const XmlFile& f, const XMLElement* p, int depth);

// The <property> (or, in a list, <item>) children of `list`.
Properties read_property_list(const XmlFile& f, const XMLElement* list, const char* child,
                              int depth) {
    if (depth > kMaxPropertyDepth)
        f.fail(list, "properties nested more than " + std::to_string(kMaxPropertyDepth) + " deep");
    Properties out;
    each_child(list, child, [&](const XMLElement* p) { out.push_back(read_property(f, p, depth)); });
    return out;
}

// A class keeps its members (its nested <properties>), a list its items
// (<item> children, nameless, each typed like a property: Tiled 1.12's form,
// the only one any Tiled version writes or reads); a scalar its value=, or,
// for multi-line strings, the element's text.
Property read_property(const XmlFile& f, const XMLElement* p, int depth) {
    Property out{str_attr(p, "name"), str_attr(p, "type", "string"), "",
                 str_attr(p, "propertytype"), {}};
    if (out.type == "class") {
        if (const XMLElement* members = p->FirstChildElement("properties"))
            out.members = read_property_list(f, members, "property", depth + 1);
    } else if (out.type == "list") {
        out.members = read_property_list(f, p, "item", depth + 1);
    } else {
        const char* value = p->Attribute("value");
        if (!value) value = p->GetText();
        out.value = value ? value : "";
    }
    return out;
}

Properties read_properties(const XmlFile& f, const XMLElement* owner) {
    const XMLElement* list = owner->FirstChildElement("properties");
    return list ? read_property_list(f, list, "property", 0) : Properties{};
}

MapObject read_object(const XmlFile& f, const XMLElement* e, Tilemap* map, ObjectFields* written);

// --- tilesets ---------------------------------------------------------------

// A size attribute of at most `max` px: image sides, spacing, margin.
int bounded_attr(const XmlFile& f, const XMLElement* e, const char* name, int64_t max) {
    const int v = size_attr(f, e, name, 0);
    if (v > max)
        f.fail(e, tag(e) + " attribute " + name + "='" + str_attr(e, name) +
                      "' is larger than the limit of " + std::to_string(max) + " px");
    return v;
}

// A colour attribute (map_color.hpp): nullopt when absent, an error naming
// the attribute and its value when malformed.
std::optional<MapColor> color_attr(const XmlFile& f, const XMLElement* e, const char* name) {
    const char* text = e->Attribute(name);
    if (!text) return std::nullopt;
    const auto c = parse_map_color(text);
    if (!c)
        f.fail(e, tag(e) + " attribute " + name + "='" + text +
                      "' is not a colour (#RRGGBB or #AARRGGBB)");
    return c;
}

// One of an attribute's named values (`parse` reads them); `fallback` when
// absent, an error naming the attribute and its value when unknown.
template <typename T, typename Parse>
T named_attr(const XmlFile& f, const XMLElement* e, const char* name, T fallback, Parse parse,
             const char* expected) {
    const char* text = e->Attribute(name);
    if (!text) return fallback;
    const std::optional<T> v = parse(std::string_view(text));
    if (!v) f.fail(e, tag(e) + " attribute " + name + "='" + text + "' is not one of " + expected);
    return *v;
}

void read_image_size(const XmlFile& f, const XMLElement* img, int& w, int& h) {
    w = bounded_attr(f, img, "width", kMaxImageSide);
    h = bounded_attr(f, img, "height", kMaxImageSide);
}

TileInfo read_tile(const XmlFile& f, const XMLElement* e, const Tileset& ts) {
    TileInfo t;
    t.id = uint_attr(f, e, "id", std::nullopt);
    t.type = type_or_class(e);
    t.properties = read_properties(f, e);
    // Only an <objectgroup> holding at least one shape counts as collision.
    const XMLElement* shapes = e->FirstChildElement("objectgroup");
    t.has_collision_shapes = shapes && shapes->FirstChildElement("object");
    if (shapes)
        each_child(shapes, "object", [&](const XMLElement* o) {
            t.objects.push_back(read_object(f, o, nullptr, nullptr));
        });
    if (shapes) check_shape_points(f.at(shapes), ts, t);
    if (const XMLElement* img = e->FirstChildElement("image")) {
        t.image = str_attr(img, "source");
        read_image_size(f, img, t.image_width, t.image_height);
    }
    if (const XMLElement* anim = e->FirstChildElement("animation"))
        each_child(anim, "frame", [&](const XMLElement* fr) {
            t.animation.push_back({uint_attr(f, fr, "tileid", std::nullopt),
                                   size_attr(f, fr, "duration", std::nullopt)});
        });
    return t;
}

// The attributes and children a <tileset> has whether embedded or in a .tsx.
void read_tileset_body(const XmlFile& f, const XMLElement* e, Tileset& ts) {
    ts.name = str_attr(e, "name");
    // Tile sizes as the map's; a tileset may leave them out (0).
    ts.tile_width = size_attr(f, e, "tilewidth", 0);
    ts.tile_height = size_attr(f, e, "tileheight", 0);
    check_tile_size(f.at(e), ts);
    ts.tile_count = size_attr(f, e, "tilecount", 0);
    ts.columns = bounded_attr(f, e, "columns", kMaxImageSide);
    ts.spacing = bounded_attr(f, e, "spacing", kMaxImageSide);
    ts.margin = bounded_attr(f, e, "margin", kMaxImageSide);
    ts.type = type_or_class(e);
    ts.properties = read_properties(f, e);
    if (const XMLElement* off = e->FirstChildElement("tileoffset")) {
        ts.tile_offset_x = int_attr(f, off, "x", 0);
        ts.tile_offset_y = int_attr(f, off, "y", 0);
    }
    if (const XMLElement* img = e->FirstChildElement("image")) {
        ts.image = str_attr(img, "source");
        read_image_size(f, img, ts.image_width, ts.image_height);
        ts.trans = color_attr(f, img, "trans");
    }
    ts.object_alignment = named_attr(f, e, "objectalignment", ObjectAlignment::Unspecified,
                                     parse_object_alignment, "unspecified, topleft, top, topright, "
                                     "left, center, right, bottomleft, bottom, bottomright");
    ts.render_size = named_attr(f, e, "tilerendersize", TileRenderSize::Tile, parse_tile_render_size,
                                "tile, grid");
    ts.fill_mode = named_attr(f, e, "fillmode", FillMode::Stretch, parse_fill_mode,
                              "stretch, preserve-aspect-fit");
    each_child(e, "tile", [&](const XMLElement* t) { ts.tiles.push_back(read_tile(f, t, ts)); });
    sort_tiles(ts);
}

// A map's <tileset>: embedded, or naming a tileset file (of either syntax)
// whose own `source` is not followed, so tilesets cannot refer to one
// another in a cycle.
Tileset read_tileset(const XmlFile& f, const XMLElement* e) {
    Tileset ts;
    ts.firstgid = uint_attr(f, e, "firstgid", std::nullopt);
    check_firstgid(f.at(e), ts.firstgid, str_attr(e, "firstgid"));
    ts.source = str_attr(e, "source");
    if (ts.source.empty()) {
        read_tileset_body(f, e, ts);
        ts.image_dir = std::filesystem::path(f.where.file).parent_path().string();
    } else {
        load_tileset_file(resolve_path(f.where.file, ts.source), *f.state, f.at(e), ts);
    }
    check_gid_range(f.at(e), ts);
    return ts;
}

void read_tilesets(const XmlFile& f, const XMLElement* root, Tilemap& map) {
    std::vector<std::pair<Tileset, int>> found;  // with the line of its element
    each_child(root, "tileset",
               [&](const XMLElement* t) { found.emplace_back(read_tileset(f, t), t->GetLineNum()); });
    add_tilesets(f.where, *f.state, std::move(found), map);
}

// --- layer data -------------------------------------------------------------

CellEncoding read_encoding(const XmlFile& f, const XMLElement* data) {
    return cell_encoding(f.at(data), data->Attribute("encoding") != nullptr,
                         str_attr(data, "encoding"), str_attr(data, "compression"));
}

// The w×h gids of a <data> or <chunk> element: <tile gid=> children, at
// most one past the expected count, or its text.
std::vector<uint32_t> element_cells(const XmlFile& f, const XMLElement* el, CellEncoding enc,
                                    int w, int h, const std::string& what) {
    std::vector<uint32_t> tiles;
    CellData data{enc, {}, &tiles};
    if (enc.kind == CellEncoding::Kind::Array) {
        const size_t max = max_array_gids(w, h);
        for (const XMLElement* t = el->FirstChildElement("tile"); t && tiles.size() < max;
             t = t->NextSiblingElement("tile"))
            tiles.push_back(uint_attr(f, t, "gid", 0u));
    } else {
        const char* text = el->GetText();
        data.text = text ? text : "";
    }
    return decode_cells(f.at(el), *f.state, data, w, h, what);
}

std::vector<ChunkHead> chunk_heads(const XmlFile& f, const XMLElement* data,
                                   std::vector<const XMLElement*>& elements) {
    std::vector<ChunkHead> heads;
    each_child(data, "chunk", [&](const XMLElement* c) {
        heads.push_back({int_attr(f, c, "x", std::nullopt), int_attr(f, c, "y", std::nullopt),
                         size_attr(f, c, "width", std::nullopt), size_attr(f, c, "height", std::nullopt),
                         c->GetLineNum(), elements.size()});
        elements.push_back(c);
    });
    return heads;
}

// An infinite layer: its chunks pasted into one dense block over their
// bounding box, whose corner becomes the layer's origin. One chunk is
// decoded at a time.
void read_chunks(const XmlFile& f, const XMLElement* data, CellEncoding enc, Tilemap& map,
                 TileLayer& l, UnknownGids& unknown) {
    std::vector<const XMLElement*> elements;
    const ChunkSpan span = chunk_span(f.at(data), *f.state, map, chunk_heads(f, data, elements), l.name);
    std::vector<uint32_t> block = start_chunked_layer(span, l);
    for (const ChunkHead& ch : span.heads) {
        const XMLElement* el = elements[ch.index];
        const std::vector<uint32_t> cells =
            element_cells(f, el, enc, ch.w, ch.h, chunk_name(ch.x, ch.y, l.name));
        check_gids(f.at(el), *f.state, map, cells, ch.w, ch.x, ch.y, l.name, unknown);
        paste_chunk(span, ch, cells, l, block);
    }
    l.cells = block;
}

std::pair<int, int> layer_size(const XmlFile& f, const XMLElement* e, const Tilemap& map) {
    return finite_layer_size(f.at(e), map, size_attr(f, e, "width", map.width),
                             size_attr(f, e, "height", map.height), str_attr(e, "name"));
}

// --- layers -----------------------------------------------------------------

// What a layer element says of itself, whatever its kind.
LayerInfo read_layer_info(const XmlFile& f, const XMLElement* e, LayerKind kind) {
    LayerInfo info;
    info.kind = kind;
    info.id = int_attr(f, e, "id", 0);
    info.name = str_attr(e, "name");
    info.type = type_or_class(e);
    info.visible = flag_attr(f, e, "visible", true);
    info.opacity = double_attr(f, e, "opacity", 1.0);
    info.offset_x = double_attr(f, e, "offsetx", 0);
    info.offset_y = double_attr(f, e, "offsety", 0);
    info.parallax_x = double_attr(f, e, "parallaxx", 1);
    info.parallax_y = double_attr(f, e, "parallaxy", 1);
    info.tint_color = str_attr(e, "tintcolor");
    if (!tint_without_hash(info.tint_color)) info.tint = color_attr(f, e, "tintcolor");  // else untinted: load.cpp warns
    info.properties = read_properties(f, e);
    return info;
}

void read_tile_layer(const XmlFile& f, const XMLElement* e, GroupState g, Tilemap& map,
                     LayerInfo& info) {
    const XMLElement* data = e->FirstChildElement("data");
    if (!data) f.fail(e, "layer '" + info.name + "' has no <data>");
    const CellEncoding enc = read_encoding(f, data);
    add_tile_layer(f.where, g, info, map, [&](TileLayer& l, UnknownGids& unknown) {
        if (map.infinite) return read_chunks(f, data, enc, map, l, unknown);
        std::tie(l.width, l.height) = layer_size(f, e, map);
        const std::vector<uint32_t> cells =
            element_cells(f, data, enc, l.width, l.height, "layer '" + l.name + "'");
        check_gids(f.at(data), *f.state, map, cells, l.width, 0, 0, l.name, unknown);
        l.cells = cells;
    });
}

// "x,y x,y …", each number strict: Tiled refuses the map otherwise.
std::vector<ObjectPoint> read_points(const XmlFile& f, const XMLElement* e) {
    const std::string written = str_attr(e, "points");
    std::vector<ObjectPoint> points;
    std::string_view rest = written;
    while (!rest.empty()) {
        const size_t start = rest.find_first_not_of(' ');
        if (start == std::string_view::npos) break;
        rest.remove_prefix(start);
        const std::string_view pair = rest.substr(0, rest.find(' '));
        rest.remove_prefix(pair.size());
        const size_t comma = pair.find(',');
        const auto x = comma == std::string_view::npos ? std::nullopt : parse_number<double>(pair.substr(0, comma));
        const auto y = x ? parse_number<double>(pair.substr(comma + 1)) : std::nullopt;
        if (!y)  // quoted in part: the list may hold a million points
            f.fail(e, tag(e) + " points='" + tmx::quoted_prefix(written, 40) + "' has '" +
                          tmx::quoted_prefix(pair, 40) + "', not an x,y pair of numbers");
        points.push_back({*x, *y});
    }
    return points;
}

ObjectText read_text(const XmlFile& f, const XMLElement* e) {
    ObjectText t;
    t.font_family = str_attr(e, "fontfamily", "sans-serif");
    t.pixel_size = size_attr(f, e, "pixelsize", 16);
    t.wrap = flag_attr(f, e, "wrap", false);
    t.bold = flag_attr(f, e, "bold", false);
    t.italic = flag_attr(f, e, "italic", false);
    t.underline = flag_attr(f, e, "underline", false);
    t.strikeout = flag_attr(f, e, "strikeout", false);
    t.kerning = flag_attr(f, e, "kerning", true);
    t.color = str_attr(e, "color", "#000000");
    t.halign = str_attr(e, "halign", "left");
    t.valign = str_attr(e, "valign", "top");
    const char* text = e->GetText();
    t.text = text ? text : "";
    return t;
}

// The shape child of an <object>, if it has one.
void read_shape(const XmlFile& f, const XMLElement* e, MapObject& o, ObjectFields& fields) {
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string_view name = c->Name();
        if (name == "ellipse") {
            o.shape = ObjectShape::Ellipse;
        } else if (name == "capsule") {  // Tiled 1.12
            o.shape = ObjectShape::Capsule;
        } else if (name == "point") {
            o.shape = ObjectShape::Point;
        } else if (name == "polygon" || name == "polyline") {
            o.shape = name == "polygon" ? ObjectShape::Polygon : ObjectShape::Polyline;
            o.points = read_points(f, c);
        } else if (name == "text") {
            o.shape = ObjectShape::Text;
            o.text = read_text(f, c);
            fields.text = true;
        } else {
            continue;
        }
        fields.shape = true;
    }
}

// An <object>; a template instance (template=) takes what it does not write
// from its template. `map` is the map it is in (nullptr in a tileset).
MapObject read_object(const XmlFile& f, const XMLElement* e, Tilemap* map, ObjectFields* written) {
    MapObject o;
    ObjectFields fields;
    fields.rotation = e->Attribute("rotation");
    fields.visible = e->Attribute("visible");
    o.id = int_attr(f, e, "id", 0);
    o.name = str_attr(e, "name");
    o.type = type_or_class(e);
    o.x = double_attr(f, e, "x", 0);
    o.y = double_attr(f, e, "y", 0);
    o.width = extent_attr(f, e, "width");
    o.height = extent_attr(f, e, "height");
    o.rotation = double_attr(f, e, "rotation", 0);
    o.gid = uint_attr(f, e, "gid", 0u);
    o.visible = flag_attr(f, e, "visible", true);
    o.properties = read_properties(f, e);
    read_shape(f, e, o, fields);
    o.shape = object_kind(o.gid, o.shape);
    if (written) *written = fields;
    if (const char* tmpl = e->Attribute("template"); tmpl && !written) {
        const auto t = load_template_file(resolve_path(f.where.file, tmpl), *f.state, f.at(e));
        merge_template(f.at(e), *f.state, *t, fields, o, map);
    }
    return o;
}

void read_object_layer(const XmlFile& f, const XMLElement* e, Tilemap& map, LayerInfo& info) {
    ObjectLayer l;
    l.name = info.name;
    l.properties = info.properties;
    l.top_down = named_attr(f, e, "draworder", true, parse_draw_order, "index, topdown");
    each_child(e, "object",
               [&](const XMLElement* o) { l.objects.push_back(read_object(f, o, &map, nullptr)); });
    info.index = map.object_layers.size();
    map.object_layers.push_back(std::move(l));
}

void read_image_layer(const XmlFile& f, const XMLElement* e, LayerInfo& info) {
    // Tiled's reader: an image layer without offsetx= is placed by its old
    // x=, y= attributes (before Tiled 1.0 they were its position), its
    // offsety= ignored. Tiled itself draws it there, so the engine does too.
    if (!e->Attribute("offsetx")) {
        info.offset_x = double_attr(f, e, "x", 0);
        info.offset_y = double_attr(f, e, "y", 0);
    }
    info.repeat_x = flag_attr(f, e, "repeatx", false);
    info.repeat_y = flag_attr(f, e, "repeaty", false);
    if (const XMLElement* img = e->FirstChildElement("image")) {
        info.image = str_attr(img, "source");
        read_image_size(f, img, info.image_width, info.image_height);
        info.image_trans = color_attr(f, img, "trans");
    }
}

// Each child of `parent` with fn(child), descending into groups (fn sees
// them too) at most kMaxGroupDepth deep.
template <class Fn>
void walk_layers(const XmlFile& f, const XMLElement* parent, int depth, Fn&& fn) {
    for (const XMLElement* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
        fn(c);
        if (std::string_view(c->Name()) != "group") continue;
        check_group_depth(f.at(c), depth);
        walk_layers(f, c, depth + 1, fn);
    }
}

// The cells a tile layer will hold, from its attributes alone.
int64_t layer_cells(const XmlFile& f, const XMLElement* e, const Tilemap& map) {
    const XMLElement* data = e->FirstChildElement("data");
    if (!data) f.fail(e, "layer '" + str_attr(e, "name") + "' has no <data>");
    if (map.infinite) {
        std::vector<const XMLElement*> elements;
        return chunk_span(f.at(data), *f.state, map, chunk_heads(f, data, elements),
                          str_attr(e, "name"))
            .cost();
    }
    const auto [w, h] = layer_size(f, e, map);
    return int64_t{w} * h;
}

// The whole map's tile-layer cells against max-cells, before any layer is
// decoded or allocated.
void check_cell_total(const XmlFile& f, const XMLElement* root, const Tilemap& map) {
    walk_layers(f, root, 0, [&](const XMLElement* c) {
        if (std::string_view(c->Name()) != "layer") return;
        take_layer_cells(f.at(c), *f.state, layer_cells(f, c, map), str_attr(c, "name"));
    });
}

// Every layer in file order into `tree`, groups nested; tile and object
// layers also into map.layers and map.object_layers.
void read_layers(const XmlFile& f, const XMLElement* parent, GroupState g, Tilemap& map,
                 std::vector<LayerInfo>& tree) {
    for (const XMLElement* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string_view name = c->Name();
        const LayerKind kind = name == "layer"         ? LayerKind::Tile
                               : name == "objectgroup" ? LayerKind::Object
                               : name == "imagelayer"  ? LayerKind::Image
                                                       : LayerKind::Group;
        if (kind == LayerKind::Group && name != "group") continue;
        LayerInfo info = read_layer_info(f, c, kind);
        if (kind == LayerKind::Tile)
            read_tile_layer(f, c, g, map, info);
        else if (kind == LayerKind::Object)
            read_object_layer(f, c, map, info);
        else if (kind == LayerKind::Image)
            read_image_layer(f, c, info);
        else  // check_cell_total bounded the depth
            read_layers(f, c, g.inside(info), map, info.children);
        tree.push_back(std::move(info));
    }
}

// --- the map ----------------------------------------------------------------

void read_map_header(const XmlFile& f, const XMLElement* root, Tilemap& map) {
    const std::string orientation = str_attr(root, "orientation", "orthogonal");
    map.width = size_attr(f, root, "width", std::nullopt);
    map.height = size_attr(f, root, "height", std::nullopt);
    map.tile_width = int_attr(f, root, "tilewidth", std::nullopt);
    map.tile_height = int_attr(f, root, "tileheight", std::nullopt);
    map.infinite = flag_attr(f, root, "infinite", false);
    map.type = type_or_class(root);
    map.background_color = str_attr(root, "backgroundcolor");
    map.background = color_attr(f, root, "backgroundcolor");
    map.parallax_origin_x = double_attr(f, root, "parallaxoriginx", 0);
    map.parallax_origin_y = double_attr(f, root, "parallaxoriginy", 0);
    map.render_order = named_attr(f, root, "renderorder", RenderOrder::RightDown, parse_render_order,
                                  "right-down, right-up, left-down, left-up");
    check_map_header(f.at(root), *f.state, map, orientation);
    map.properties = read_properties(f, root);
}

}  // namespace

Tilemap read_tmx_map(std::string_view text, const Where& file, LoadState& s) {
    XmlFile f{file, s};
    parse_xml(f, text);
    const XMLElement* root = root_named(f, "map");
    Tilemap map;
    map.path = file.file;
    map.extra_solid_gids = s.options.solid_gids;
    read_map_header(f, root, map);
    check_cell_total(f, root, map);
    // Tilesets first, wherever they sit, so layers can check their gids.
    read_tilesets(f, root, map);
    read_layers(f, root, {}, map, map.layer_tree);
    if (map.infinite) fit_infinite_bounds(f.at(root), s, map);
    return map;
}

void read_tsx_tileset(std::string_view text, const Where& file, LoadState& s, Tileset& ts) {
    XmlFile f{file, s};
    parse_xml(f, text);
    const XMLElement* root = f.doc.RootElement();
    if (!root || std::strcmp(root->Name(), "tileset") != 0)
        f.fail(root, "expected a <tileset> root element");
    read_tileset_body(f, root, ts);
    ts.image_dir = std::filesystem::path(file.file).parent_path().string();
}

ObjectTemplate read_tx_template(std::string_view text, const Where& file, LoadState& s) {
    XmlFile f{file, s};
    parse_xml(f, text);
    const XMLElement* root = root_named(f, "template");
    const XMLElement* object = root->FirstChildElement("object");
    if (!object) f.fail(root, "template has no <object>");
    ObjectTemplate t;
    t.object = read_object(f, object, nullptr, &t.fields);
    if (const XMLElement* ts = root->FirstChildElement("tileset")) {
        t.tileset_firstgid = uint_attr(f, ts, "firstgid", std::nullopt);
        check_firstgid(f.at(ts), t.tileset_firstgid, str_attr(ts, "firstgid"));
        t.tileset_path = resolve_path(file.file, str_attr(ts, "source"));
    }
    return t;
}

}  // namespace ds::build
