// load_tilemap: a TMX map and its TSX tilesets read with tinyxml2 (semantics §7).
// Every failure is a MapError naming the file and, where there is one, the
// line of the offending element; unknown elements and attributes are skipped.
// A file is hostile until shown otherwise: only regular files are read,
// within MapLimits' bytes, and the cells of every tile layer are counted
// from the attributes against MapLimits' cells before any is decoded
// (docs/limits.org, "Maps and tilesets").
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <tuple>
#include <type_traits>
#include <vector>

#include "decode.hpp"
#include "map_bounds.hpp"
#include "read_file.hpp"
#include "tilemap.hpp"

namespace ds {

namespace {

using tinyxml2::XMLElement;

// What one load may still use: the caller's limits, the bytes left to read
// (the map and its tilesets share them) and the tile-layer cells.
struct LoadState {
    explicit LoadState(const MapLimits& l) : limits(l), bytes_left(l.max_bytes), cells(l.max_cells) {}
    MapLimits limits;
    int64_t bytes_left;
    CellBudget cells;
};

// One XML file being read. `note` is appended to every message so that an
// error inside a .tsx also says which map used it.
struct XmlFile {
    XmlFile(std::string p, std::string n, LoadState& s)
        : path(std::move(p)), note(std::move(n)), state(&s) {}

    std::string path;
    std::string note;
    LoadState* state;  // shared by the map and its tilesets
    tinyxml2::XMLDocument doc;

    [[noreturn]] void fail(const XMLElement* at, const std::string& message) const {
        throw MapError(path, at ? at->GetLineNum() : 0, message + note);
    }
};

std::string tag(const XMLElement* e) { return std::string("<") + e->Name() + ">"; }

std::string size_text(int64_t w, int64_t h) { return std::to_string(w) + "x" + std::to_string(h); }

// A regular file's contents, drawn from the load's byte budget; nullopt with
// `error` set to why not.
std::optional<std::string> read_counted(LoadState& s, const std::string& path,
                                        std::string& error) {
    const char* limit = s.bytes_left < s.limits.max_bytes ? "max-bytes leaves" : "max-bytes allows";
    auto text = tmx::read_regular_file(path, s.bytes_left, limit, error);
    if (text) s.bytes_left -= static_cast<int64_t>(text->size());
    return text;
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

void parse_xml(XmlFile& f, std::string_view text) {
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
        out.push_back({str_attr(p, "name"), str_attr(p, "type", "string"), value ? value : "", "", {}});
    });
    return out;
}

// --- tilesets ---------------------------------------------------------------

// A size attribute of at most `max` px: image sides, spacing, margin.
int bounded_attr(const XmlFile& f, const XMLElement* e, const char* name, int64_t max) {
    const int v = size_attr(f, e, name, 0);
    if (v > max)
        f.fail(e, tag(e) + " attribute " + name + "='" + str_attr(e, name) +
                      "' is larger than the limit of " + std::to_string(max) + " px");
    return v;
}

void read_image_size(const XmlFile& f, const XMLElement* img, int& w, int& h) {
    w = bounded_attr(f, img, "width", kMaxImageSide);
    h = bounded_attr(f, img, "height", kMaxImageSide);
}

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
        read_image_size(f, img, t.image_width, t.image_height);
    }
    return t;
}

// Tile sizes as the map's; a tileset may leave them out (0).
void read_tile_size(const XmlFile& f, const XMLElement* e, Tileset& ts) {
    ts.tile_width = size_attr(f, e, "tilewidth", 0);
    ts.tile_height = size_attr(f, e, "tileheight", 0);
    if (ts.tile_width > kMaxTileSize || ts.tile_height > kMaxTileSize)
        f.fail(e, "tileset '" + ts.name + "' " + tile_size_problem(ts.tile_width, ts.tile_height));
}

// The attributes and children a <tileset> has whether embedded or in a .tsx.
void read_tileset_body(const XmlFile& f, const XMLElement* e, Tileset& ts) {
    ts.name = str_attr(e, "name");
    read_tile_size(f, e, ts);
    ts.tile_count = size_attr(f, e, "tilecount", 0);
    ts.columns = bounded_attr(f, e, "columns", kMaxImageSide);
    ts.spacing = bounded_attr(f, e, "spacing", kMaxImageSide);
    ts.margin = bounded_attr(f, e, "margin", kMaxImageSide);
    if (const XMLElement* img = e->FirstChildElement("image")) {
        ts.image = str_attr(img, "source");
        read_image_size(f, img, ts.image_width, ts.image_height);
    }
    each_child(e, "tile", [&](const XMLElement* t) { ts.tiles.push_back(read_tile(f, t)); });
    std::stable_sort(ts.tiles.begin(), ts.tiles.end(),
                     [](const TileInfo& a, const TileInfo& b) { return a.id < b.id; });
}

// A .tsx is read as a tileset body only: a `source` inside it is not
// followed, so tilesets cannot nest or refer to one another in a cycle.
void read_external_tileset(const XmlFile& map_file, const XMLElement* e, Tileset& ts) {
    const std::string tsx =
        (std::filesystem::path(map_file.path).parent_path() / ts.source).string();
    std::string error;
    const auto text = read_counted(*map_file.state, tsx, error);
    if (!text) map_file.fail(e, "cannot open tileset '" + tsx + "': " + error);
    XmlFile f{tsx, " (tileset of " + map_file.path + ":" + std::to_string(e->GetLineNum()) + ")",
              *map_file.state};
    parse_xml(f, *text);
    const XMLElement* root = f.doc.RootElement();
    if (!root || std::strcmp(root->Name(), "tileset") != 0)
        f.fail(root, "expected a <tileset> root element");
    read_tileset_body(f, root, ts);
    ts.image_dir = std::filesystem::path(tsx).parent_path().string();
}

// Its gids, firstgid … firstgid+tilecount−1, must all be gids.
void check_gid_range(const XmlFile& f, const XMLElement* e, const Tileset& ts) {
    if (ts.tile_count == 0 || static_cast<uint32_t>(ts.tile_count - 1) <= kGidMask - ts.firstgid)
        return;
    f.fail(e, "tileset '" + ts.name + "' firstgid=" + std::to_string(ts.firstgid) +
                  " with tilecount=" + std::to_string(ts.tile_count) + " runs past the largest gid " +
                  std::to_string(kGidMask));
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
    check_gid_range(f, e, ts);
    return ts;
}

// Every <tileset> of the map, sorted by firstgid; two with one firstgid
// would make its gids ambiguous.
void read_tilesets(const XmlFile& f, const XMLElement* root, Tilemap& map) {
    std::vector<std::pair<Tileset, int>> found;  // with the line of its element
    each_child(root, "tileset",
               [&](const XMLElement* t) { found.emplace_back(read_tileset(f, t), t->GetLineNum()); });
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first.firstgid < b.first.firstgid;
    });
    for (size_t i = 1; i < found.size(); ++i)
        if (found[i].first.firstgid == found[i - 1].first.firstgid) {
            const int first = std::min(found[i].second, found[i - 1].second),
                      second = std::max(found[i].second, found[i - 1].second);
            throw MapError(f.path, second,
                           "<tileset> firstgid='" + std::to_string(found[i].first.firstgid) +
                               "' is also the firstgid of the tileset on line " +
                               std::to_string(first) + f.note);
        }
    for (auto& [ts, line] : found) map.tilesets.push_back(std::move(ts));
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

// At most max gids: past that the layer is wrong whatever follows.
std::vector<uint32_t> xml_tiles(const XmlFile& f, const XMLElement* el, size_t max) {
    std::vector<uint32_t> gids;
    for (const XMLElement* t = el->FirstChildElement("tile"); t && gids.size() < max;
         t = t->NextSiblingElement("tile"))
        gids.push_back(uint_attr(f, t, "gid", 0u));
    return gids;
}

// The gids of `el`: `expected` of them when the data is right, and never
// more than expected + 1 from text (CSV, XML) or expected from compressed
// data, however large the file says it is.
std::vector<uint32_t> decode_gids(const XmlFile& f, const XMLElement* el, Encoding enc,
                                  size_t expected, const std::string& what) {
    const char* text = el->GetText();
    const std::string_view body = text ? text : "";
    try {
        switch (enc.kind) {
            case Encoding::Kind::Xml:
                return xml_tiles(f, el, expected + 1);
            case Encoding::Kind::Csv:
                return tmx::parse_csv(body, expected + 1);
            case Encoding::Kind::Base64:
                break;
        }
        const std::vector<uint8_t> bytes = tmx::decode_base64(body);
        if (enc.compression == tmx::Compression::None) return tmx::gids_from_bytes(bytes);
        return tmx::gids_from_bytes(tmx::decompress(enc.compression, bytes, expected * 4));
    } catch (const tmx::DecodeError& err) {
        f.fail(el, what + ": " + err.what());
    }
}

std::string over_cell_limit(const XmlFile& f) {
    return "more than the loader's limit of " + std::to_string(f.state->limits.max_cells) +
           " cells (max-cells)";
}

// The w×h gids of a <data> or <chunk> element; `what` names it in messages.
std::vector<uint32_t> decode_cells(const XmlFile& f, const XMLElement* el, Encoding enc, int w,
                                   int h, const std::string& what) {
    if (exceeds(w, h, f.state->limits.max_cells))
        f.fail(el, what + " is " + size_text(w, h) + " cells, " + over_cell_limit(f));
    const int64_t expected = int64_t{w} * h;
    std::vector<uint32_t> gids = decode_gids(f, el, enc, static_cast<size_t>(expected), what);
    if (static_cast<int64_t>(gids.size()) == expected) return gids;
    // Text stops being read one past the expected count.
    const bool cut = enc.kind != Encoding::Kind::Base64 && static_cast<int64_t>(gids.size()) > expected;
    const std::string count = cut ? "more than " + std::to_string(expected) : std::to_string(gids.size());
    f.fail(el, what + " has " + count + " cells, expected " + size_text(w, h) + " = " +
                   std::to_string(expected));
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
        if (ts && ts->has_tile(gid - ts->firstgid)) continue;
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

// A <chunk>'s place and size, read before any chunk is decoded.
struct ChunkHead {
    const XMLElement* el;
    int64_t x, y;
    int w, h;
};

// An infinite layer's chunks: their bounding box and the cells they hold.
struct ChunkSpan {
    std::vector<ChunkHead> heads;
    int64_t c0 = 0, r0 = 0, c1 = 0, r1 = 0;
    int64_t cells = 0;  // summed over the chunks (overlaps count twice)

    int64_t area() const { return (c1 - c0) * (r1 - r0); }
    void add(const ChunkHead& h) {
        const bool first = c0 == c1;
        c0 = first ? h.x : std::min(c0, h.x);
        r0 = first ? h.y : std::min(r0, h.y);
        c1 = first ? h.x + h.w : std::max(c1, h.x + h.w);
        r1 = first ? h.y + h.h : std::max(r1, h.y + h.h);
    }
};

std::string chunk_name(int64_t x, int64_t y, const std::string& layer) {
    return "chunk (" + std::to_string(x) + ", " + std::to_string(y) + ") of layer '" + layer + "'";
}

ChunkHead read_chunk_head(const XmlFile& f, const XMLElement* c) {
    return {c, int_attr(f, c, "x", std::nullopt), int_attr(f, c, "y", std::nullopt),
            size_attr(f, c, "width", std::nullopt), size_attr(f, c, "height", std::nullopt)};
}

// From attributes alone: no chunk is decoded until the whole layer is known
// to fit the cell limit and the coordinate range.
ChunkSpan chunk_span(const XmlFile& f, const XMLElement* data, const Tilemap& map,
                     const std::string& layer) {
    const int64_t max = f.state->limits.max_cells;
    ChunkSpan s;
    each_child(data, "chunk", [&](const XMLElement* c) {
        const ChunkHead h = read_chunk_head(f, c);
        if (exceeds(h.w, h.h, max - s.cells))
            f.fail(c, chunk_name(h.x, h.y, layer) + " (" + size_text(h.w, h.h) +
                          ") brings the layer's chunks to " + over_cell_limit(f));
        s.cells += int64_t{h.w} * h.h;
        if (h.w > 0 && h.h > 0) s.add(h);
        s.heads.push_back(h);
    });
    const int64_t w = s.c1 - s.c0, h = s.r1 - s.r0;
    if (exceeds(w, h, max) || w > INT_MAX || h > INT_MAX)
        f.fail(data, "the chunks of layer '" + layer + "' span " + size_text(w, h) + " cells, " +
                         over_cell_limit(f));
    for (const std::string& p : {extent_problem(s.c0, w, map.tile_width, "column"),
                                 extent_problem(s.r0, h, map.tile_height, "row")})
        if (!p.empty()) f.fail(data, "layer '" + layer + "': " + p);
    return s;
}

// An infinite layer: its chunks pasted into one dense block over their
// bounding box, whose corner becomes the layer's origin. One chunk is
// decoded at a time.
void read_chunks(const XmlFile& f, const XMLElement* data, Encoding enc, const Tilemap& map,
                 TileLayer& l) {
    const ChunkSpan s = chunk_span(f, data, map, l.name);
    l.origin_col = s.c0;
    l.origin_row = s.r0;
    l.width = static_cast<int>(s.c1 - s.c0);
    l.height = static_cast<int>(s.r1 - s.r0);
    std::vector<uint32_t> block(static_cast<size_t>(s.area()), 0);
    for (const ChunkHead& ch : s.heads) {
        const std::vector<uint32_t> cells =
            decode_cells(f, ch.el, enc, ch.w, ch.h, chunk_name(ch.x, ch.y, l.name));
        check_gids(f, ch.el, map, cells, ch.w, ch.x, ch.y, l.name);
        for (int r = 0; r < ch.h; ++r)
            std::copy_n(cells.begin() + static_cast<ptrdiff_t>(r) * ch.w, ch.w,
                        block.begin() + (ch.y - s.r0 + r) * l.width + (ch.x - s.c0));
    }
    l.cells = block;
}

// A finite map's layer covers exactly the map (Tiled: "always the same as
// the map width"): cells outside the map would be solid yet unseen.
std::pair<int, int> finite_layer_size(const XmlFile& f, const XMLElement* e, const Tilemap& map,
                                      const std::string& name) {
    const int w = size_attr(f, e, "width", map.width), h = size_attr(f, e, "height", map.height);
    if (w != map.width || h != map.height)
        f.fail(e, "layer '" + name + "' is " + size_text(w, h) + " cells but the map is " +
                      size_text(map.width, map.height));
    return {w, h};
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
        std::tie(l.width, l.height) = finite_layer_size(f, e, map, l.name);
        const std::vector<uint32_t> cells = decode_cells(f, data, enc, l.width, l.height, "layer '" + l.name + "'");
        check_gids(f, data, map, cells, l.width, 0, 0, l.name);
        l.cells = cells;
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

// Each child of `parent` with fn(child, depth), descending into groups
// (fn sees them too) at most kMaxGroupDepth deep.
template <class Fn>
void walk_layers(const XmlFile& f, const XMLElement* parent, int depth, Fn&& fn) {
    for (const XMLElement* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
        fn(c);
        if (std::string_view(c->Name()) != "group") continue;
        if (depth >= kMaxGroupDepth)
            f.fail(c, "<group> nested more than " + std::to_string(kMaxGroupDepth) + " deep");
        walk_layers(f, c, depth + 1, fn);
    }
}

// The cells a tile layer will hold, from its attributes alone.
int64_t layer_cells(const XmlFile& f, const XMLElement* e, const Tilemap& map) {
    const std::string name = str_attr(e, "name");
    const XMLElement* data = e->FirstChildElement("data");
    if (!data) f.fail(e, "layer '" + name + "' has no <data>");
    if (map.infinite) {
        const ChunkSpan s = chunk_span(f, data, map, name);
        return std::max(s.area(), s.cells);  // the dense block, and what is decoded
    }
    const auto [w, h] = finite_layer_size(f, e, map, name);
    return int64_t{w} * h;
}

// The whole map's tile-layer cells against max-cells, before any layer is
// decoded or allocated.
void check_cell_total(const XmlFile& f, const XMLElement* root, const Tilemap& map) {
    CellBudget& budget = f.state->cells;
    walk_layers(f, root, 0, [&](const XMLElement* c) {
        if (std::string_view(c->Name()) != "layer") return;
        const int64_t cells = layer_cells(f, c, map);
        if (!budget.take(cells))
            f.fail(c, "layer '" + str_attr(c, "name") + "' (" + std::to_string(cells) +
                          " cells) brings the map's tile layers to " + over_cell_limit(f));
    });
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
            read_layers(f, c, inner, map);  // check_cell_total bounded the depth
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
    if (std::string p = tile_size_problem(map.tile_width, map.tile_height); !p.empty())
        f.fail(root, p);
    map.infinite = flag_attr(f, root, "infinite", false);
    // An infinite map's width and height bound nothing: Tiled lets its
    // chunks grow in every direction, so only the cell limit applies.
    if (!map.infinite)
        if (std::string p = map_size_problem(map.width, map.height, map.tile_width,
                                             map.tile_height, f.state->limits.max_cells);
            !p.empty())
            f.fail(root, p);
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
    const int64_t w = c1 - c0, h = r1 - r0;
    // The solid grid is allocated over this box.
    if (exceeds(w, h, f.state->limits.max_cells) || w > INT_MAX || h > INT_MAX)
        f.fail(root, "the map's chunks span " + size_text(w, h) + " cells, " + over_cell_limit(f));
    map.width = static_cast<int>(w);
    map.height = static_cast<int>(h);
}

void check_limits(const std::string& path, const MapLimits& limits) {
    if (limits.max_cells <= 0)
        throw MapError(path, 0, "max-cells " + std::to_string(limits.max_cells) + " is not positive");
    if (limits.max_bytes <= 0)
        throw MapError(path, 0, "max-bytes " + std::to_string(limits.max_bytes) + " is not positive");
}

Tilemap parse_map(const std::string_view text, const std::string& path,
                  std::vector<uint32_t> solid_gids, LoadState& state) {
    XmlFile f{path, "", state};
    parse_xml(f, text);
    const XMLElement* root = f.doc.RootElement();
    if (!root || std::strcmp(root->Name(), "map") != 0)
        f.fail(root,
               root ? "root element is " + tag(root) + ", expected <map>" : "no <map> element");

    Tilemap map;
    map.path = path;
    map.extra_solid_gids = std::move(solid_gids);
    read_map_header(f, root, map);
    check_cell_total(f, root, map);
    // Tilesets first, wherever they sit, so layers can check their gids.
    read_tilesets(f, root, map);
    read_layers(f, root, {}, map);
    if (map.infinite) fit_infinite_bounds(f, root, map);
    return map;
}

}  // namespace

Tilemap load_tilemap(const std::string& path, std::vector<uint32_t> solid_gids,
                     const MapLimits& limits) {
    check_limits(path, limits);
    LoadState state(limits);
    std::string error;
    const auto text = read_counted(state, path, error);
    if (!text) throw MapError(path, 0, "cannot open map: " + error);
    return parse_map(*text, path, std::move(solid_gids), state);
}

Tilemap load_tilemap(const std::string& path, const LoadOptions& options) {
    return load_tilemap(path, options.solid_gids, options.limits);
}

Tilemap parse_tilemap(std::string_view text, const std::string& path,
                      std::vector<uint32_t> solid_gids, const MapLimits& limits) {
    check_limits(path, limits);
    LoadState state(limits);
    if (static_cast<int64_t>(text.size()) > limits.max_bytes)
        throw MapError(path, 0, "map is " + std::to_string(text.size()) + " bytes, more than the " +
                                    std::to_string(limits.max_bytes) + " bytes max-bytes allows");
    state.bytes_left -= static_cast<int64_t>(text.size());
    return parse_map(text, path, std::move(solid_gids), state);
}

}  // namespace ds
