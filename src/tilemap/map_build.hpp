// SPDX-License-Identifier: MIT
// What every map reader (TMX, JSON) does once a file's syntax is parsed:
// the load's budgets, where errors point, the cell checks made from sizes
// before anything is decoded, decoding and pasting tile data, the gid check
// (an error or a warning), tileset order, layer solidity, group state,
// infinite-map bounds and the template merge. Knows no file syntax: the
// readers hand it model pieces and the line they came from.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "decode.hpp"
#include "map_bounds.hpp"
#include "tilemap.hpp"

namespace ds::build {

struct ObjectTemplate;

// What one load may still use: the caller's options, the bytes left to read
// (the map, its tilesets and templates share them), the tile-layer cells,
// and the templates already read (a template used twice is read once).
struct LoadState {
    explicit LoadState(const LoadOptions& o)
        : options(o), bytes_left(o.limits.max_bytes), cells(o.limits.max_cells) {}
    LoadOptions options;
    int64_t bytes_left;
    CellBudget cells;
    std::map<std::string, std::shared_ptr<const ObjectTemplate>> templates;  // by resolved path

    const MapLimits& limits() const { return options.limits; }
};

// Where a message points: a file, a line in it (0 when the format has none,
// as JSON here), and a note appended to every message, such as
// " (tileset of map.tmx:3)", so an error in a tileset says which map used it.
struct Where {
    std::string file;
    int line = 0;
    std::string note;

    Where at(int l) const { return {file, l, note}; }
    [[noreturn]] void fail(const std::string& message) const;
};

std::string size_text(int64_t w, int64_t h);  // "WxH"
std::string over_cell_limit(const LoadState& s);  // "more than the loader's limit of N cells (max-cells)"

// Refuses limits that are not positive (MapError on `path`, line 0).
void check_limits(const std::string& path, const MapLimits& limits);

// A regular file's contents, drawn from the load's byte budget; nullopt with
// `error` set to why not.
std::optional<std::string> read_counted(LoadState& s, const std::string& path, std::string& error);
// `text` (already in memory) drawn from the budget; MapError when too large.
void count_text(LoadState& s, std::string_view text, const std::string& path);

// `relative` as written in the file at `from`, resolved against its folder.
std::string resolve_path(const std::string& from, const std::string& relative);

// --- the map ----------------------------------------------------------------

// Orientation, sizes and tile sizes of the map header, already read:
// refuses a non-orthogonal map, bad tile sizes and (finite maps) bad sizes.
void check_map_header(const Where& w, const LoadState& s, const Tilemap& map,
                      const std::string& orientation);

// --- tilesets ---------------------------------------------------------------

// firstgid in 1 … kGidMask; `written` is the value as the file has it.
void check_firstgid(const Where& w, uint32_t firstgid, const std::string& written);
// Tile sizes of a tileset within kMaxTileSize.
void check_tile_size(const Where& w, const Tileset& ts);
// Each collision shape of tile `t` has at most kMaxShapePoints points.
void check_shape_points(const Where& w, const Tileset& ts, const TileInfo& t);
// Its gids, firstgid … firstgid+tilecount−1 (and, in an image collection,
// firstgid + its largest tile id), must all be gids.
void check_gid_range(const Where& w, const Tileset& ts);
// Sorts by id, so Tileset::tile can search.
void sort_tiles(Tileset& ts);

// Every tileset of the map with the line it was declared on, sorted by
// firstgid into map.tilesets; two with one firstgid are refused (their
// gids would be ambiguous). One that says nothing (no tile size, no
// image, no tiles, as a `{}` .tsj) is a warning on the map, or refused by
// a strict load: whatever the map draws from it is missing.
void add_tilesets(const Where& w, const LoadState& s, std::vector<std::pair<Tileset, int>> found, Tilemap& map);

// --- tile layers ------------------------------------------------------------

// How a layer's or chunk's data is written. Array: already a list of gids
// (TMX <tile gid=> elements, a JSON array).
struct CellEncoding {
    enum class Kind : uint8_t { Array, Csv, Base64 } kind = Kind::Array;
    tmx::Compression compression = tmx::Compression::None;
};
// From the format's names: encoding "" (array), "csv" or "base64";
// compression "", "zlib", "gzip" or "zstd" (base64 only). `has_encoding`
// tells an absent encoding from an empty one (which is refused).
CellEncoding cell_encoding(const Where& w, bool has_encoding, const std::string& encoding,
                           const std::string& compression);

// A layer's or chunk's data as the reader found it: text for Csv/Base64,
// gids for Array (the reader stops at max_array_gids(w, h): one past the
// expected count already tells the data is too long).
struct CellData {
    CellEncoding encoding;
    std::string_view text;
    const std::vector<uint32_t>* gids = nullptr;
};
size_t max_array_gids(int w, int h);

// The w×h gids of one layer's or chunk's data; `what` names it in messages.
// Never decodes more than w×h (+1 for text) gids, whatever the data says.
std::vector<uint32_t> decode_cells(const Where& w, const LoadState& s, const CellData& data,
                                   int width, int height, const std::string& what);

// A finite map's layer covers exactly the map; returns its size.
std::pair<int, int> finite_layer_size(const Where& w, const Tilemap& map, int width, int height,
                                      const std::string& layer);

// Takes a tile layer's cells (counted from sizes alone) from the budget.
void take_layer_cells(const Where& w, LoadState& s, int64_t cells, const std::string& layer);

// A chunk's place and size, read before any chunk is decoded; `line` and
// `index` let the reader find it again.
struct ChunkHead {
    int64_t x = 0, y = 0;
    int w = 0, h = 0;
    int line = 0;
    size_t index = 0;
};

// An infinite layer's chunks: their bounding box and the cells they hold.
struct ChunkSpan {
    std::vector<ChunkHead> heads;
    int64_t c0 = 0, r0 = 0, c1 = 0, r1 = 0;
    int64_t cells = 0;  // summed over the chunks (overlaps count twice)

    int64_t area() const { return (c1 - c0) * (r1 - r0); }
    // The dense block and what is decoded: what the layer costs.
    int64_t cost() const { return area() > cells ? area() : cells; }
};
std::string chunk_name(int64_t x, int64_t y, const std::string& layer);
// The span of `heads` (`w` points at the layer's data), checked against the
// cell limit and the coordinate range before any chunk is decoded.
ChunkSpan chunk_span(const Where& w, const LoadState& s, const Tilemap& map,
                     std::vector<ChunkHead> heads, const std::string& layer);
// Sizes layer `l` over the span (origin, width, height) and returns its
// zeroed block of cells.
std::vector<uint32_t> start_chunked_layer(const ChunkSpan& span, TileLayer& l);
void paste_chunk(const ChunkSpan& span, const ChunkHead& head, const std::vector<uint32_t>& cells,
                 const TileLayer& l, std::vector<uint32_t>& block);

// Gids beyond every tileset in one layer: the first one and how many.
struct UnknownGids {
    int64_t count = 0;
    int64_t col = 0, row = 0;
    uint32_t raw = 0;
    int line = 0;
};
// Checks gids of cells starting at (col0, row0), `width` per row. Strict:
// the first unknown gid is a MapError; else each is tallied in `unknown`.
void check_gids(const Where& w, const LoadState& s, const Tilemap& map,
                const std::vector<uint32_t>& gids, int width, int64_t col0, int64_t row0,
                const std::string& layer, UnknownGids& unknown);
// One warning on the map for a layer with unknown gids (none when none).
void warn_unknown_gids(const Where& w, const std::string& layer, const UnknownGids& unknown,
                       Tilemap& map);

// From a layer's solid/collision property.
LayerSolidity layer_solidity(const Properties& props);

// What enclosing groups pass down: visibility and opacity multiply,
// offsets add.
struct GroupState {
    bool visible = true;
    double opacity = 1.0;
    double offset_x = 0, offset_y = 0;

    GroupState inside(const LayerInfo& group) const;
    // A layer's own values combined with its groups'.
    void apply(const LayerInfo& own, TileLayer& l) const;
};
// A tile layer of either format: its own attributes (`info`) and its
// groups' (`g`) give its name, drawing state and solidity; fill(layer,
// unknown) decodes its cells into it (chunks, or one block), noting the gids
// no tileset holds. It then joins map.layers, info.index pointing at it,
// with one warning for those gids.
template <class Fill>
void add_tile_layer(const Where& w, const GroupState& g, LayerInfo& info, Tilemap& map, Fill fill) {
    TileLayer l;
    l.name = info.name;
    g.apply(info, l);
    l.properties = info.properties;
    l.solidity = layer_solidity(l.properties);
    UnknownGids unknown;
    fill(l, unknown);
    warn_unknown_gids(w, l.name, unknown, map);
    info.index = map.layers.size();
    map.layers.push_back(std::move(l));
}

// Refuses a group nested deeper than kMaxGroupDepth (depth counts from 0).
void check_group_depth(const Where& w, int depth);

// An infinite map's size is the bounding box of every layer's chunks.
void fit_infinite_bounds(const Where& w, const LoadState& s, Tilemap& map);

// --- templates --------------------------------------------------------------

// Which of an object's fields its file writes: a template instance keeps
// those and takes the rest from its template.
struct ObjectFields {
    bool rotation = false, visible = false, shape = false, text = false;
};

// A template file (.tx/.tj): its object and, for a tile object, the
// tileset its gid is counted in (firstgid and the resolved source path).
struct ObjectTemplate {
    std::string path;
    MapObject object;
    ObjectFields fields;
    uint32_t tileset_firstgid = 0;  // 0 when the template names no tileset
    std::string tileset_path;       // resolved
};

// The instance `object` (fields written as `fields`) made from `tmpl`, as
// Tiled does: the template's fields are the defaults, the instance's override
// as merge_template's comment says; properties are the template's, then the instance's
// replacing by name. The template's gid is mapped into the map's gid space
// (map_tile_gid; with no map, as in a tileset's own objects, the gid is
// kept as the template has it). object.template_path becomes tmpl.path.
void merge_template(const Where& w, LoadState& s, const ObjectTemplate& tmpl,
                    const ObjectFields& fields, MapObject& object, Tilemap* map);

// The map's gid for a template's gid: through the map's tileset with the
// same resolved source, which is loaded and added after the last one when
// the map lacks it (as Tiled does).
uint32_t map_tile_gid(const Where& w, LoadState& s, const ObjectTemplate& tmpl, Tilemap& map);

// Tile objects as Tiled shows them (its "effective class"): an object
// layer's object with a gid and no class of its own takes its tile's, and
// its properties are the tile's, then its own (templates merged already)
// replacing by name. A gid no tileset holds leaves the object as it is.
void inherit_tile_classes(Tilemap& map);

}  // namespace ds::build
