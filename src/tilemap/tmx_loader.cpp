// load_tilemap: a TMX map and its TSX tilesets read with tinyxml2 (semantics §7).
// Every failure is a MapError naming the file and, where there is one, the
// line of the offending element; unknown elements and attributes are skipped.
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include "decode.hpp"
#include "tilemap.hpp"

namespace ds {

namespace {

using tinyxml2::XMLElement;

// The most cells one layer or a whole map may span: 8192×8192. Dense layers
// are allocated over their bounding box, so without a bound two far-apart
// chunks of an infinite map could demand terabytes.
constexpr int64_t kMaxCells = int64_t{1} << 26;

// Each side checked first so the product cannot overflow.
bool too_many_cells(int64_t w, int64_t h) {
    return w > kMaxCells || h > kMaxCells || w * h > kMaxCells;
}

// One XML file being read. `note` is appended to every message so that an
// error inside a .tsx also says which map used it.
struct XmlFile {
    XmlFile(std::string p, std::string n) : path(std::move(p)), note(std::move(n)) {}

    std::string path;
    std::string note;
    tinyxml2::XMLDocument doc;

    [[noreturn]] void fail(const XMLElement* at, const std::string& message) const {
        throw MapError(path, at ? at->GetLineNum() : 0, message + note);
    }
};

std::string tag(const XMLElement* e) { return std::string("<") + e->Name() + ">"; }

// Whole file contents, or nullopt with `error` set to the system's reason.
std::optional<std::string> read_text(const std::string& path, std::string& error) {
    // A directory opens fine on Linux and then reads as nothing at all.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        error = "is a directory";
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// tinyxml2's ErrorStr repeats the id and line; keep only its detail.
std::string xml_error(const tinyxml2::XMLDocument& doc) {
    std::string message = std::string("malformed XML (") + doc.ErrorName() + ")";
    const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
    const size_t at = full.find("Line number=");
    const size_t colon = at == std::string::npos ? at : full.find(": ", at);
    if (colon != std::string::npos) message += ": " + full.substr(colon + 2);
    return message;
}

void parse_xml(XmlFile& f, const std::string& text) {
    if (f.doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
        throw MapError(f.path, f.doc.ErrorLineNum(), xml_error(f.doc) + f.note);
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

Properties read_properties(const XMLElement* owner) {
    Properties out;
    const XMLElement* list = owner->FirstChildElement("properties");
    if (!list) return out;
    each_child(list, "property", [&](const XMLElement* p) {
        // Multi-line strings are written as the element's text, not value=.
        const char* value = p->Attribute("value");
        if (!value) value = p->GetText();
        out.push_back({str_attr(p, "name"), str_attr(p, "type", "string"), value ? value : ""});
    });
    return out;
}

// --- tilesets ---------------------------------------------------------------

TileInfo read_tile(const XmlFile& f, const XMLElement* e) {
    TileInfo t;
    t.id = uint_attr(f, e, "id", std::nullopt);
    t.type = type_or_class(e);
    t.properties = read_properties(e);
    // Only an <objectgroup> holding at least one shape counts as collision.
    const XMLElement* shapes = e->FirstChildElement("objectgroup");
    t.has_collision_shapes = shapes && shapes->FirstChildElement("object");
    if (const XMLElement* img = e->FirstChildElement("image")) {
        t.image = str_attr(img, "source");
        t.image_width = size_attr(f, img, "width", 0);
        t.image_height = size_attr(f, img, "height", 0);
    }
    return t;
}

// The attributes and children a <tileset> has whether embedded or in a .tsx.
void read_tileset_body(const XmlFile& f, const XMLElement* e, Tileset& ts) {
    ts.name = str_attr(e, "name");
    ts.tile_width = size_attr(f, e, "tilewidth", 0);
    ts.tile_height = size_attr(f, e, "tileheight", 0);
    ts.tile_count = size_attr(f, e, "tilecount", 0);
    ts.columns = size_attr(f, e, "columns", 0);
    ts.spacing = size_attr(f, e, "spacing", 0);
    ts.margin = size_attr(f, e, "margin", 0);
    if (const XMLElement* img = e->FirstChildElement("image")) {
        ts.image = str_attr(img, "source");
        ts.image_width = size_attr(f, img, "width", 0);
        ts.image_height = size_attr(f, img, "height", 0);
    }
    each_child(e, "tile", [&](const XMLElement* t) { ts.tiles.push_back(read_tile(f, t)); });
    std::stable_sort(ts.tiles.begin(), ts.tiles.end(),
                     [](const TileInfo& a, const TileInfo& b) { return a.id < b.id; });
}

void read_external_tileset(const XmlFile& map_file, const XMLElement* e, Tileset& ts) {
    const std::string tsx =
        (std::filesystem::path(map_file.path).parent_path() / ts.source).string();
    std::string error;
    const auto text = read_text(tsx, error);
    if (!text) map_file.fail(e, "cannot open tileset '" + tsx + "': " + error);
    XmlFile f{tsx, " (tileset of " + map_file.path + ":" + std::to_string(e->GetLineNum()) + ")"};
    parse_xml(f, *text);
    const XMLElement* root = f.doc.RootElement();
    if (!root || std::strcmp(root->Name(), "tileset") != 0)
        f.fail(root, "expected a <tileset> root element");
    read_tileset_body(f, root, ts);
    ts.image_dir = std::filesystem::path(tsx).parent_path().string();
}

Tileset read_tileset(const XmlFile& f, const XMLElement* e) {
    Tileset ts;
    ts.firstgid = uint_attr(f, e, "firstgid", std::nullopt);
    if (ts.firstgid == 0 || ts.firstgid > kGidMask)
        f.fail(e, "<tileset> firstgid='" + str_attr(e, "firstgid") + "' is out of range");
    ts.source = str_attr(e, "source");
    if (ts.source.empty()) {
        read_tileset_body(f, e, ts);
        ts.image_dir = std::filesystem::path(f.path).parent_path().string();
    }
    else
        read_external_tileset(f, e, ts);
    return ts;
}

// --- layer data -------------------------------------------------------------

struct Encoding {
    enum class Kind : uint8_t { Xml, Csv, Base64 } kind = Kind::Xml;
    tmx::Compression compression = tmx::Compression::None;
};

Encoding read_encoding(const XmlFile& f, const XMLElement* data) {
    Encoding enc;
    const std::string name = str_attr(data, "encoding");
    const std::string comp = str_attr(data, "compression");
    if (name == "csv")
        enc.kind = Encoding::Kind::Csv;
    else if (name == "base64")
        enc.kind = Encoding::Kind::Base64;
    else if (data->Attribute("encoding"))
        f.fail(data, "unknown encoding '" + name + "'");
    if (comp.empty()) return enc;
    if (comp == "zlib")
        enc.compression = tmx::Compression::Zlib;
    else if (comp == "gzip")
        enc.compression = tmx::Compression::Gzip;
    else if (comp == "zstd")
        enc.compression = tmx::Compression::Zstd;
    else
        f.fail(data, "unknown compression '" + comp + "'");
    if (enc.kind != Encoding::Kind::Base64)
        f.fail(data, "compression '" + comp + "' needs base64 encoding");
    return enc;
}

std::vector<uint32_t> xml_tiles(const XmlFile& f, const XMLElement* el) {
    std::vector<uint32_t> gids;
    each_child(el, "tile",
               [&](const XMLElement* t) { gids.push_back(uint_attr(f, t, "gid", 0u)); });
    return gids;
}

std::vector<uint32_t> decode_gids(const XmlFile& f, const XMLElement* el, Encoding enc,
                                  size_t expected) {
    const char* text = el->GetText();
    const std::string_view body = text ? text : "";
    try {
        switch (enc.kind) {
            case Encoding::Kind::Xml:
                return xml_tiles(f, el);
            case Encoding::Kind::Csv:
                return tmx::parse_csv(body);
            case Encoding::Kind::Base64:
                break;
        }
        const std::vector<uint8_t> bytes = tmx::decode_base64(body);
        if (enc.compression == tmx::Compression::None) return tmx::gids_from_bytes(bytes);
        return tmx::gids_from_bytes(tmx::decompress(enc.compression, bytes, expected * 4));
    } catch (const tmx::DecodeError& err) {
        f.fail(el, err.what());
    }
}

// The w×h gids of a <data> or <chunk> element; `what` names it in messages.
std::vector<uint32_t> decode_cells(const XmlFile& f, const XMLElement* el, Encoding enc, int w,
                                   int h, const std::string& what) {
    const int64_t expected = int64_t{w} * h;
    if (too_many_cells(w, h))
        f.fail(el, what + " is " + std::to_string(w) + "x" + std::to_string(h) +
                       " cells, more than the loader's limit of " + std::to_string(kMaxCells));
    std::vector<uint32_t> gids = decode_gids(f, el, enc, static_cast<size_t>(expected));
    if (static_cast<int64_t>(gids.size()) != expected)
        f.fail(el, what + " has " + std::to_string(gids.size()) + " cells, expected " +
                       std::to_string(w) + "x" + std::to_string(h) + " = " +
                       std::to_string(expected));
    return gids;
}

// Every non-empty gid must fall inside a tileset's range, so that lookups
// never silently land in the wrong tileset.
void check_gids(const XmlFile& f, const XMLElement* el, const Tilemap& map,
                const std::vector<uint32_t>& gids, int w, int64_t col0, int64_t row0,
                const std::string& layer) {
    for (size_t i = 0; i < gids.size(); ++i) {
        const uint32_t gid = gids[i] & kGidMask;
        if (gid == 0) continue;
        const Tileset* ts = map.tileset_for(gid);
        if (ts &&
            (ts->tile_count == 0 || gid - ts->firstgid < static_cast<uint32_t>(ts->tile_count)))
            continue;
        const int64_t col = col0 + static_cast<int64_t>(i % w),
                      row = row0 + static_cast<int64_t>(i / w);
        std::string raw;
        if (gids[i] != gid) {
            char buf[24];
            std::snprintf(buf, sizeof buf, " (raw 0x%08X)", gids[i]);
            raw = buf;
        }
        f.fail(el, "gid " + std::to_string(gid) + raw + " at cell (" + std::to_string(col) + ", " +
                       std::to_string(row) + ") of layer '" + layer + "' is beyond every tileset");
    }
}

struct Chunk {
    int64_t x = 0, y = 0;
    int w = 0, h = 0;
    std::vector<uint32_t> cells;
};

Chunk read_chunk(const XmlFile& f, const XMLElement* c, Encoding enc, const Tilemap& map,
                 const std::string& layer) {
    Chunk ch;
    ch.x = int_attr(f, c, "x", std::nullopt);
    ch.y = int_attr(f, c, "y", std::nullopt);
    ch.w = size_attr(f, c, "width", std::nullopt);
    ch.h = size_attr(f, c, "height", std::nullopt);
    const std::string what = "chunk (" + std::to_string(ch.x) + ", " + std::to_string(ch.y) +
                             ") of layer '" + layer + "'";
    ch.cells = decode_cells(f, c, enc, ch.w, ch.h, what);
    check_gids(f, c, map, ch.cells, ch.w, ch.x, ch.y, layer);
    return ch;
}

// An infinite layer: its chunks pasted into one dense block over their
// bounding box, whose corner becomes the layer's origin.
void read_chunks(const XmlFile& f, const XMLElement* data, Encoding enc, const Tilemap& map,
                 TileLayer& l) {
    std::vector<Chunk> chunks;
    each_child(data, "chunk",
               [&](const XMLElement* c) { chunks.push_back(read_chunk(f, c, enc, map, l.name)); });
    int64_t c0 = 0, r0 = 0, c1 = 0, r1 = 0;
    bool any = false;
    for (const Chunk& ch : chunks) {
        if (ch.w == 0 || ch.h == 0) continue;
        c0 = any ? std::min(c0, ch.x) : ch.x;
        r0 = any ? std::min(r0, ch.y) : ch.y;
        c1 = any ? std::max(c1, ch.x + ch.w) : ch.x + ch.w;
        r1 = any ? std::max(r1, ch.y + ch.h) : ch.y + ch.h;
        any = true;
    }
    if (too_many_cells(c1 - c0, r1 - r0))
        f.fail(data, "the chunks of layer '" + l.name + "' span " + std::to_string(c1 - c0) + "x" +
                         std::to_string(r1 - r0) + " cells, more than the loader's limit of " +
                         std::to_string(kMaxCells));
    l.origin_col = c0;
    l.origin_row = r0;
    l.width = static_cast<int>(c1 - c0);
    l.height = static_cast<int>(r1 - r0);
    l.cells.assign(static_cast<size_t>(l.width) * static_cast<size_t>(l.height), 0);
    for (const Chunk& ch : chunks)
        for (int r = 0; r < ch.h; ++r)
            std::copy_n(ch.cells.begin() + static_cast<ptrdiff_t>(r) * ch.w, ch.w,
                        l.cells.begin() + (ch.y - r0 + r) * l.width + (ch.x - c0));
}

// --- layers -----------------------------------------------------------------

// What an enclosing <group> passes down to the layers inside it.
struct GroupState {
    bool visible = true;
    double opacity = 1.0;
};

LayerSolidity layer_solidity(const Properties& props) {
    const Property* p = find_property(props, "solid");
    if (!p) p = find_property(props, "collision");
    if (!p) return LayerSolidity::FromTiles;
    return property_is_true(*p) ? LayerSolidity::All : LayerSolidity::None;
}

void read_tile_layer(const XmlFile& f, const XMLElement* e, GroupState g, Tilemap& map) {
    TileLayer l;
    l.name = str_attr(e, "name");
    l.visible = g.visible && flag_attr(f, e, "visible", true);
    l.opacity = g.opacity * double_attr(f, e, "opacity", 1.0);
    l.properties = read_properties(e);
    l.solidity = layer_solidity(l.properties);
    const XMLElement* data = e->FirstChildElement("data");
    if (!data) f.fail(e, "layer '" + l.name + "' has no <data>");
    const Encoding enc = read_encoding(f, data);
    if (map.infinite) {
        read_chunks(f, data, enc, map, l);
    } else {
        l.width = size_attr(f, e, "width", map.width);
        l.height = size_attr(f, e, "height", map.height);
        l.cells = decode_cells(f, data, enc, l.width, l.height, "layer '" + l.name + "'");
        check_gids(f, data, map, l.cells, l.width, 0, 0, l.name);
    }
    map.layers.push_back(std::move(l));
}

MapObject read_object(const XmlFile& f, const XMLElement* e) {
    MapObject o;
    o.id = int_attr(f, e, "id", 0);
    o.name = str_attr(e, "name");
    o.type = type_or_class(e);
    o.x = double_attr(f, e, "x", 0);
    o.y = double_attr(f, e, "y", 0);
    o.width = double_attr(f, e, "width", 0);
    o.height = double_attr(f, e, "height", 0);
    o.rotation = double_attr(f, e, "rotation", 0);
    o.gid = uint_attr(f, e, "gid", 0u);
    o.visible = flag_attr(f, e, "visible", true);
    o.properties = read_properties(e);
    return o;
}

void read_object_layer(const XmlFile& f, const XMLElement* e, Tilemap& map) {
    ObjectLayer l;
    l.name = str_attr(e, "name");
    l.properties = read_properties(e);
    each_child(e, "object", [&](const XMLElement* o) { l.objects.push_back(read_object(f, o)); });
    map.object_layers.push_back(std::move(l));
}

// Tile and object layers in file order, descending into groups.
void read_layers(const XmlFile& f, const XMLElement* parent, GroupState g, Tilemap& map) {
    for (const XMLElement* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string_view name = c->Name();
        if (name == "layer") {
            read_tile_layer(f, c, g, map);
        } else if (name == "objectgroup") {
            read_object_layer(f, c, map);
        } else if (name == "group") {
            const GroupState inner{g.visible && flag_attr(f, c, "visible", true),
                                   g.opacity * double_attr(f, c, "opacity", 1.0)};
            read_layers(f, c, inner, map);
        }
    }
}

// --- the map ----------------------------------------------------------------

void read_map_header(const XmlFile& f, const XMLElement* root, Tilemap& map) {
    const std::string orientation = str_attr(root, "orientation", "orthogonal");
    if (orientation != "orthogonal")
        f.fail(root, "unsupported orientation '" + orientation + "' (only orthogonal maps)");
    map.width = size_attr(f, root, "width", std::nullopt);
    map.height = size_attr(f, root, "height", std::nullopt);
    map.tile_width = int_attr(f, root, "tilewidth", std::nullopt);
    map.tile_height = int_attr(f, root, "tileheight", std::nullopt);
    if (map.tile_width <= 0 || map.tile_height <= 0)
        f.fail(root, "tile size " + std::to_string(map.tile_width) + "x" +
                         std::to_string(map.tile_height) + " is not positive");
    map.infinite = flag_attr(f, root, "infinite", false);
    if (!map.infinite && too_many_cells(map.width, map.height))
        f.fail(root, "map is " + std::to_string(map.width) + "x" + std::to_string(map.height) +
                         " cells, more than the loader's limit of " + std::to_string(kMaxCells));
    map.properties = read_properties(root);
}

// An infinite map's size is the bounding box of every layer's chunks.
void fit_infinite_bounds(const XmlFile& f, const XMLElement* root, Tilemap& map) {
    int64_t c0 = 0, r0 = 0, c1 = 0, r1 = 0;
    bool any = false;
    for (const TileLayer& l : map.layers) {
        if (l.width == 0 || l.height == 0) continue;
        c0 = any ? std::min(c0, l.origin_col) : l.origin_col;
        r0 = any ? std::min(r0, l.origin_row) : l.origin_row;
        c1 = any ? std::max(c1, l.origin_col + l.width) : l.origin_col + l.width;
        r1 = any ? std::max(r1, l.origin_row + l.height) : l.origin_row + l.height;
        any = true;
    }
    if (too_many_cells(c1 - c0, r1 - r0))
        f.fail(root, "the map's chunks span " + std::to_string(c1 - c0) + "x" +
                         std::to_string(r1 - r0) + " cells, more than the loader's limit of " +
                         std::to_string(kMaxCells));
    map.width = static_cast<int>(c1 - c0);
    map.height = static_cast<int>(r1 - r0);
}

}  // namespace

Tilemap load_tilemap(const std::string& path, std::vector<uint32_t> solid_gids) {
    std::string error;
    const auto text = read_text(path, error);
    if (!text) throw MapError(path, 0, "cannot open map: " + error);
    XmlFile f{path, ""};
    parse_xml(f, *text);
    const XMLElement* root = f.doc.RootElement();
    if (!root || std::strcmp(root->Name(), "map") != 0)
        f.fail(root,
               root ? "root element is " + tag(root) + ", expected <map>" : "no <map> element");

    Tilemap map;
    map.path = path;
    map.extra_solid_gids = std::move(solid_gids);
    read_map_header(f, root, map);
    // Tilesets first, wherever they sit, so layers can check their gids.
    each_child(root, "tileset",
               [&](const XMLElement* t) { map.tilesets.push_back(read_tileset(f, t)); });
    std::stable_sort(map.tilesets.begin(), map.tilesets.end(),
                     [](const Tileset& a, const Tileset& b) { return a.firstgid < b.firstgid; });
    read_layers(f, root, {}, map);
    if (map.infinite) fit_infinite_bounds(f, root, map);
    return map;
}

}  // namespace ds
