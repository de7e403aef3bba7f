// SPDX-License-Identifier: MIT
// The format-neutral half of loading a map (map_build.hpp). Every failure is
// a MapError through Where, so it names the file, the line where the format
// has one, and the value.
#include "map_build.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <filesystem>

#include "bounded_file.hpp"
#include "map_objects.hpp"
#include "readers.hpp"

namespace ds::build {

void Where::fail(const std::string& message) const { throw MapError(file, line, message + note); }

std::string size_text(int64_t w, int64_t h) { return std::to_string(w) + "x" + std::to_string(h); }

std::string over_cell_limit(const LoadState& s) {
    return "more than the loader's limit of " + std::to_string(s.limits().max_cells) +
           " cells (max-cells)";
}

void check_limits(const std::string& path, const MapLimits& limits) {
    if (limits.max_cells <= 0)
        throw MapError(path, 0, "max-cells " + std::to_string(limits.max_cells) + " is not positive");
    if (limits.max_bytes <= 0)
        throw MapError(path, 0, "max-bytes " + std::to_string(limits.max_bytes) + " is not positive");
}

std::optional<std::string> read_counted(LoadState& s, const std::string& path, std::string& error) {
    const char* limit = s.bytes_left < s.limits().max_bytes ? "max-bytes leaves" : "max-bytes allows";
    auto text = read_bounded_file(path, s.bytes_left, limit, error);
    if (text) s.bytes_left -= static_cast<int64_t>(text->size());
    return text;
}

void count_text(LoadState& s, std::string_view text, const std::string& path) {
    if (static_cast<int64_t>(text.size()) > s.bytes_left)
        throw MapError(path, 0, "map is " + std::to_string(text.size()) + " bytes, more than the " +
                                    std::to_string(s.limits().max_bytes) + " bytes max-bytes allows");
    s.bytes_left -= static_cast<int64_t>(text.size());
}

std::string resolve_path(const std::string& from, const std::string& relative) {
    return (std::filesystem::path(from).parent_path() / relative).string();
}

// --- the map ----------------------------------------------------------------

void check_map_header(const Where& w, const LoadState& s, const Tilemap& map,
                      const std::string& orientation) {
    if (orientation != "orthogonal")
        w.fail("unsupported orientation '" + orientation + "' (only orthogonal maps)");
    if (std::string p = tile_size_problem(map.tile_width, map.tile_height); !p.empty()) w.fail(p);
    // An infinite map's width and height bound nothing: Tiled lets its
    // chunks grow in every direction, so only the cell limit applies.
    if (!map.infinite)
        if (std::string p = map_size_problem(map.width, map.height, map.tile_width,
                                             map.tile_height, s.limits().max_cells);
            !p.empty())
            w.fail(p);
}

// --- tilesets ---------------------------------------------------------------

void check_firstgid(const Where& w, uint32_t firstgid, const std::string& written) {
    if (firstgid == 0 || firstgid > kGidMask)
        w.fail("<tileset> firstgid='" + written + "' is out of range");
}

void check_tile_size(const Where& w, const Tileset& ts) {
    if (ts.tile_width > kMaxTileSize || ts.tile_height > kMaxTileSize)
        w.fail("tileset '" + ts.name + "' " + tile_size_problem(ts.tile_width, ts.tile_height));
}

void check_shape_points(const Where& w, const Tileset& ts, const TileInfo& t) {
    for (const MapObject& o : t.objects)
        if (o.points.size() > kMaxShapePoints)
            w.fail("tileset '" + ts.name + "', tile " + std::to_string(t.id) + ": a collision shape of " +
                   std::to_string(o.points.size()) + " points, more than the " + std::to_string(kMaxShapePoints) +
                   " a shape may have");
}

void check_gid_range(const Where& w, const Tileset& ts) {
    if (ts.tile_count > 0 && static_cast<uint32_t>(ts.tile_count - 1) > kGidMask - ts.firstgid)
        w.fail("tileset '" + ts.name + "' firstgid=" + std::to_string(ts.firstgid) +
               " with tilecount=" + std::to_string(ts.tile_count) + " runs past the largest gid " +
               std::to_string(kGidMask));
    // Sorted: the last tile has the largest id.
    if (ts.image_collection() && !ts.tiles.empty() && ts.tiles.back().id > kGidMask - ts.firstgid)
        w.fail("tileset '" + ts.name + "' firstgid=" + std::to_string(ts.firstgid) + " with tile id " +
               std::to_string(ts.tiles.back().id) + " runs past the largest gid " +
               std::to_string(kGidMask));
}

void sort_tiles(Tileset& ts) {
    std::stable_sort(ts.tiles.begin(), ts.tiles.end(),
                     [](const TileInfo& a, const TileInfo& b) { return a.id < b.id; });
}

void add_tilesets(const Where& w, const LoadState& s, std::vector<std::pair<Tileset, int>> found, Tilemap& map) {
    for (const auto& [ts, line] : found) {
        // Only one that says nothing at all: a tileset with a tile size
        // but no picture yet is a common stand-in (and the test maps').
        if (!ts.image.empty() || !ts.tiles.empty() || ts.tile_width > 0 || ts.tile_height > 0) continue;
        // Named by the map's own words (its source as written, or an
        // embedded tileset's name), not by anything read from the file.
        const std::string which =
            ts.source.empty() ? "tileset '" + ts.name + "'" : "tileset file '" + ts.source + "'";
        const std::string problem =
            which + " says nothing (no tile size, no image, no tiles): its gids are missing, non-solid tiles";
        if (s.options.strict) w.at(line).fail(problem);
        const Where at = w.at(line);
        map.warnings.push_back((at.line > 0 ? at.file + ":" + std::to_string(at.line) : at.file) + ": " +
                               problem + w.note);
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first.firstgid < b.first.firstgid;
    });
    for (size_t i = 1; i < found.size(); ++i)
        if (found[i].first.firstgid == found[i - 1].first.firstgid) {
            const int first = std::min(found[i].second, found[i - 1].second),
                      second = std::max(found[i].second, found[i - 1].second);
            w.at(second).fail("<tileset> firstgid='" + std::to_string(found[i].first.firstgid) +
                              "' is also the firstgid of the tileset on line " +
                              std::to_string(first));
        }
    for (auto& [ts, line] : found) map.tilesets.push_back(std::move(ts));
}

// --- tile layers ------------------------------------------------------------

CellEncoding cell_encoding(const Where& w, bool has_encoding, const std::string& encoding,
                           const std::string& compression) {
    CellEncoding enc;
    if (encoding == "csv")
        enc.kind = CellEncoding::Kind::Csv;
    else if (encoding == "base64")
        enc.kind = CellEncoding::Kind::Base64;
    else if (has_encoding)
        w.fail("unknown encoding '" + encoding + "'");
    if (compression.empty()) return enc;
    if (compression == "zlib")
        enc.compression = tmx::Compression::Zlib;
    else if (compression == "gzip")
        enc.compression = tmx::Compression::Gzip;
    else if (compression == "zstd")
        enc.compression = tmx::Compression::Zstd;
    else
        w.fail("unknown compression '" + compression + "'");
    if (enc.kind != CellEncoding::Kind::Base64)
        w.fail("compression '" + compression + "' needs base64 encoding");
    return enc;
}

size_t max_array_gids(int w, int h) { return static_cast<size_t>(int64_t{w} * h) + 1; }

namespace {

// At most expected + 1 gids from text or an array, expected from
// compressed data, however large the data says it is.
std::vector<uint32_t> decode_gids(const Where& w, const CellData& data, size_t expected,
                                  const std::string& what) {
    try {
        switch (data.encoding.kind) {
            case CellEncoding::Kind::Array: {
                if (!data.gids) return {};
                const size_t n = std::min(data.gids->size(), expected + 1);
                return {data.gids->begin(), data.gids->begin() + static_cast<ptrdiff_t>(n)};
            }
            case CellEncoding::Kind::Csv:
                return tmx::parse_csv(data.text, expected + 1);
            case CellEncoding::Kind::Base64:
                break;
        }
        const std::vector<uint8_t> bytes = tmx::decode_base64(data.text);
        if (data.encoding.compression == tmx::Compression::None) return tmx::gids_from_bytes(bytes);
        return tmx::gids_from_bytes(tmx::decompress(data.encoding.compression, bytes, expected * 4));
    } catch (const tmx::DecodeError& err) {
        w.fail(what + ": " + err.what());
    }
}

}  // namespace

std::vector<uint32_t> decode_cells(const Where& w, const LoadState& s, const CellData& data,
                                   int width, int height, const std::string& what) {
    if (exceeds(width, height, s.limits().max_cells))
        w.fail(what + " is " + size_text(width, height) + " cells, " + over_cell_limit(s));
    const int64_t expected = int64_t{width} * height;
    std::vector<uint32_t> gids = decode_gids(w, data, static_cast<size_t>(expected), what);
    if (static_cast<int64_t>(gids.size()) == expected) return gids;
    // Text and arrays stop being read one past the expected count.
    const bool cut = data.encoding.kind != CellEncoding::Kind::Base64 &&
                     static_cast<int64_t>(gids.size()) > expected;
    const std::string count = cut ? "more than " + std::to_string(expected) : std::to_string(gids.size());
    w.fail(what + " has " + count + " cells, expected " + size_text(width, height) + " = " +
           std::to_string(expected));
}

std::pair<int, int> finite_layer_size(const Where& w, const Tilemap& map, int width, int height,
                                      const std::string& layer) {
    if (width != map.width || height != map.height)
        w.fail("layer '" + layer + "' is " + size_text(width, height) + " cells but the map is " +
               size_text(map.width, map.height));
    return {width, height};
}

void take_layer_cells(const Where& w, LoadState& s, int64_t cells, const std::string& layer) {
    if (!s.cells.take(cells))
        w.fail("layer '" + layer + "' (" + std::to_string(cells) +
               " cells) brings the map's tile layers to " + over_cell_limit(s));
}

std::string chunk_name(int64_t x, int64_t y, const std::string& layer) {
    return "chunk (" + std::to_string(x) + ", " + std::to_string(y) + ") of layer '" + layer + "'";
}

ChunkSpan chunk_span(const Where& w, const LoadState& s, const Tilemap& map,
                     std::vector<ChunkHead> heads, const std::string& layer) {
    const int64_t max = s.limits().max_cells;
    ChunkSpan span;
    bool any = false;
    for (const ChunkHead& h : heads) {
        if (exceeds(h.w, h.h, max - span.cells))
            w.at(h.line).fail(chunk_name(h.x, h.y, layer) + " (" + size_text(h.w, h.h) +
                              ") brings the layer's chunks to " + over_cell_limit(s));
        span.cells += int64_t{h.w} * h.h;
        if (h.w <= 0 || h.h <= 0) continue;
        span.c0 = any ? std::min(span.c0, h.x) : h.x;
        span.r0 = any ? std::min(span.r0, h.y) : h.y;
        span.c1 = any ? std::max(span.c1, h.x + h.w) : h.x + h.w;
        span.r1 = any ? std::max(span.r1, h.y + h.h) : h.y + h.h;
        any = true;
    }
    span.heads = std::move(heads);
    const int64_t cw = span.c1 - span.c0, ch = span.r1 - span.r0;
    if (exceeds(cw, ch, max) || cw > INT_MAX || ch > INT_MAX)
        w.fail("the chunks of layer '" + layer + "' span " + size_text(cw, ch) + " cells, " +
               over_cell_limit(s));
    for (const std::string& p : {extent_problem(span.c0, cw, map.tile_width, "column"),
                                 extent_problem(span.r0, ch, map.tile_height, "row")})
        if (!p.empty()) w.fail("layer '" + layer + "': " + p);
    return span;
}

std::vector<uint32_t> start_chunked_layer(const ChunkSpan& span, TileLayer& l) {
    l.origin_col = span.c0;
    l.origin_row = span.r0;
    l.width = static_cast<int>(span.c1 - span.c0);
    l.height = static_cast<int>(span.r1 - span.r0);
    return std::vector<uint32_t>(static_cast<size_t>(span.area()), 0);
}

void paste_chunk(const ChunkSpan& span, const ChunkHead& head, const std::vector<uint32_t>& cells,
                 const TileLayer& l, std::vector<uint32_t>& block) {
    // An empty chunk adds nothing to the span: it may lie anywhere, even
    // where an offset into the block would not (the fuzzer's x="2000000000").
    if (head.w <= 0 || head.h <= 0) return;
    for (int r = 0; r < head.h; ++r)
        std::copy_n(cells.begin() + static_cast<ptrdiff_t>(r) * head.w, head.w,
                    block.begin() + (head.y - span.r0 + r) * l.width + (head.x - span.c0));
}

namespace {

std::string gid_text(uint32_t raw) {
    std::string text = std::to_string(raw & kGidMask);
    if (raw != (raw & kGidMask)) {
        char buf[24];
        std::snprintf(buf, sizeof buf, " (raw 0x%08X)", raw);
        text += buf;
    }
    return text;
}

std::string cell_text(int64_t col, int64_t row) {
    return "(" + std::to_string(col) + ", " + std::to_string(row) + ")";
}

}  // namespace

void check_gids(const Where& w, const LoadState& s, const Tilemap& map,
                const std::vector<uint32_t>& gids, int width, int64_t col0, int64_t row0,
                const std::string& layer, UnknownGids& unknown) {
    for (size_t i = 0; i < gids.size(); ++i) {
        const uint32_t gid = gids[i] & kGidMask;
        if (gid == 0) continue;
        const Tileset* ts = map.tileset_for(gid);
        if (ts && ts->has_tile(gid - ts->firstgid)) continue;
        const int64_t col = col0 + static_cast<int64_t>(i % width),
                      row = row0 + static_cast<int64_t>(i / width);
        if (s.options.strict)
            w.fail("gid " + gid_text(gids[i]) + " at cell " + cell_text(col, row) + " of layer '" +
                   layer + "' is beyond every tileset");
        if (unknown.count++ == 0) unknown = {1, col, row, gids[i], w.line};
    }
}

void warn_unknown_gids(const Where& w, const std::string& layer, const UnknownGids& unknown,
                       Tilemap& map) {
    if (unknown.count == 0) return;
    const Where at = w.at(unknown.line);
    const std::string place = at.line > 0 ? at.file + ":" + std::to_string(at.line) : at.file;
    const std::string others =
        unknown.count == 1 ? "" : " (" + std::to_string(unknown.count) + " cells in all)";
    map.warnings.push_back(place + ": gid " + gid_text(unknown.raw) + " at cell " +
                           cell_text(unknown.col, unknown.row) + " of layer '" + layer +
                           "' is beyond every tileset" + others +
                           "; loaded as a missing, non-solid tile" + w.note);
}

LayerSolidity layer_solidity(const Properties& props) {
    const Property* p = find_property(props, "solid");
    if (!p) p = find_property(props, "collision");
    if (!p) return LayerSolidity::FromTiles;
    return property_is_true(*p) ? LayerSolidity::All : LayerSolidity::None;
}

GroupState GroupState::inside(const LayerInfo& group) const {
    return {visible && group.visible, opacity * group.opacity, offset_x + group.offset_x,
            offset_y + group.offset_y};
}

void GroupState::apply(const LayerInfo& own, TileLayer& l) const {
    l.visible = visible && own.visible;
    l.opacity = opacity * own.opacity;
    l.offset_x = offset_x + own.offset_x;
    l.offset_y = offset_y + own.offset_y;
}

void check_group_depth(const Where& w, int depth) {
    if (depth >= kMaxGroupDepth)
        w.fail("<group> nested more than " + std::to_string(kMaxGroupDepth) + " deep");
}

void fit_infinite_bounds(const Where& w, const LoadState& s, Tilemap& map) {
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
    const int64_t cw = c1 - c0, ch = r1 - r0;
    // The solid grid is allocated over this box.
    if (exceeds(cw, ch, s.limits().max_cells) || cw > INT_MAX || ch > INT_MAX)
        w.fail("the map's chunks span " + size_text(cw, ch) + " cells, " + over_cell_limit(s));
    map.width = static_cast<int>(cw);
    map.height = static_cast<int>(ch);
}

// --- templates --------------------------------------------------------------

namespace {

bool same_file(const std::string& a, const std::string& b) {
    return std::filesystem::path(a).lexically_normal() == std::filesystem::path(b).lexically_normal();
}

// The first gid after every tileset of the map: where Tiled puts one more.
uint32_t next_firstgid(const Tilemap& map) {
    uint64_t next = 1;
    for (const Tileset& ts : map.tilesets) {
        uint64_t count = static_cast<uint64_t>(ts.tile_count);
        for (const TileInfo& t : ts.tiles) count = std::max<uint64_t>(count, uint64_t{t.id} + 1);
        next = std::max<uint64_t>(next, ts.firstgid + std::max<uint64_t>(count, 1));
    }
    return static_cast<uint32_t>(std::min<uint64_t>(next, uint64_t{kGidMask} + 1));
}

const Tileset* tileset_from(const Tilemap& map, const std::string& resolved) {
    for (const Tileset& ts : map.tilesets)
        if (!ts.source.empty() && same_file(resolve_path(map.path, ts.source), resolved)) return &ts;
    return nullptr;
}

void merge_properties(const Properties& defaults, Properties& own) {
    Properties merged = defaults;
    for (Property& p : own) {
        auto it = std::find_if(merged.begin(), merged.end(),
                               [&](const Property& d) { return d.name == p.name; });
        if (it != merged.end())
            *it = std::move(p);
        else
            merged.push_back(std::move(p));
    }
    own = std::move(merged);
}

}  // namespace

uint32_t map_tile_gid(const Where& w, LoadState& s, const ObjectTemplate& tmpl, Tilemap& map) {
    const uint32_t raw = tmpl.object.gid, flips = raw & ~kGidMask, gid = raw & kGidMask;
    if (gid == 0) return 0;
    if (tmpl.tileset_firstgid == 0 || gid < tmpl.tileset_firstgid)
        w.fail("template '" + tmpl.path + "' has a tile object with gid " + std::to_string(gid) +
               " but no tileset for it");
    const uint32_t local = gid - tmpl.tileset_firstgid;
    const Tileset* ts = tileset_from(map, tmpl.tileset_path);
    if (!ts) {
        Tileset added;
        added.firstgid = next_firstgid(map);
        if (added.firstgid > kGidMask)
            w.fail("template '" + tmpl.path + "': no gid is left for its tileset '" +
                   tmpl.tileset_path + "'");
        const auto map_dir = std::filesystem::path(map.path).parent_path().lexically_normal();
        added.source = std::filesystem::path(tmpl.tileset_path)
                           .lexically_normal()
                           .lexically_relative(map_dir.empty() ? "." : map_dir)
                           .string();
        if (added.source.empty()) added.source = tmpl.tileset_path;  // no relative path to it
        load_tileset_file(tmpl.tileset_path, s, w, added);
        check_gid_range(w, added);
        map.tilesets.push_back(std::move(added));  // after the last: still sorted
        ts = &map.tilesets.back();
    }
    if (local > kGidMask - ts->firstgid)
        w.fail("template '" + tmpl.path + "': its tile " + std::to_string(local) +
               " runs past the largest gid");
    return (ts->firstgid + local) | flips;
}

void merge_template(const Where& w, LoadState& s, const ObjectTemplate& tmpl,
                    const ObjectFields& fields, MapObject& object, Tilemap* map) {
    const MapObject& t = tmpl.object;
    // Tiled's rules (libtiled's readObject and MapObject::syncWithTemplate):
    // the position is always the instance's; a name or class overrides only
    // when not empty, a size only when both sides are positive (then both),
    // a gid only when not 0; the rest whenever written.
    if (object.name.empty()) object.name = t.name;
    if (object.type.empty()) object.type = t.type;
    if (!(object.width > 0 && object.height > 0)) object.width = t.width, object.height = t.height;
    if (!fields.rotation) object.rotation = t.rotation;
    if (!fields.visible) object.visible = t.visible;
    if (!fields.shape) {
        object.shape = t.shape;
        object.points = t.points;
    }
    if (!fields.text) object.text = t.text;
    if (object.gid == 0) object.gid = map ? map_tile_gid(w, s, tmpl, *map) : t.gid;
    object.shape = object_kind(object.gid, object.shape);
    merge_properties(t.properties, object.properties);
    object.template_path = tmpl.path;
}

void inherit_tile_classes(Tilemap& map) {
    for (ObjectLayer& layer : map.object_layers)
        for (MapObject& o : layer.objects) {
            const uint32_t gid = o.gid & kGidMask;
            const Tileset* ts = gid ? map.tileset_for(gid) : nullptr;
            const TileInfo* tile = ts ? ts->tile(gid - ts->firstgid) : nullptr;
            if (!tile) continue;
            if (o.type.empty()) o.type = tile->type;
            if (!tile->properties.empty()) merge_properties(tile->properties, o.properties);
        }
}

}  // namespace ds::build
