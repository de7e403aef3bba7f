// SPDX-License-Identifier: MIT
#include "tilemap.hpp"

#include "tile_shapes.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>
#include <unordered_map>

namespace ds {

namespace {

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

// gid_known for a nonzero masked gid whose tileset_for is ts.
bool known_in(const Tilemap& map, const Tileset* ts, uint32_t gid) {
    return map.tilesets.empty() || (ts && ts->has_tile(gid - ts->firstgid));
}

std::string where(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) : file;
}

struct Bounds {
    int64_t col0 = 0, row0 = 0, col1 = 0, row1 = 0;  // half-open
    bool empty = true;

    void add(const TileLayer& l) {
        if (l.width <= 0 || l.height <= 0) return;
        const int64_t c1 = l.origin_col + l.width, r1 = l.origin_row + l.height;
        if (empty) {
            *this = {l.origin_col, l.origin_row, c1, r1, false};
            return;
        }
        col0 = std::min(col0, l.origin_col);
        row0 = std::min(row0, l.origin_row);
        col1 = std::max(col1, c1);
        row1 = std::max(row1, r1);
    }
};

}  // namespace

const Property* find_property(const Properties& props, std::string_view name) {
    for (const Property& p : props)
        if (p.name == name) return &p;
    return nullptr;
}

bool property_is_true(const Property& p) { return iequals(p.value, "true") || p.value == "1"; }

const TileInfo* Tileset::tile(uint32_t local_id) const {
    const auto it = std::lower_bound(tiles.begin(), tiles.end(), local_id,
                                     [](const TileInfo& t, uint32_t id) { return t.id < id; });
    return it != tiles.end() && it->id == local_id ? &*it : nullptr;
}

bool Tileset::image_collection() const {
    return image.empty() &&
           std::any_of(tiles.begin(), tiles.end(), [](const TileInfo& t) { return !t.image.empty(); });
}

bool Tileset::has_tile(uint32_t local_id) const {
    if (tile_count == 0) return true;  // the file does not say
    if (image_collection()) return tile(local_id) != nullptr;
    return local_id < static_cast<uint32_t>(tile_count);
}

uint32_t tiles_in_image(const Tileset& ts, int image_w, int image_h, int columns) {
    const int64_t tw = ts.tile_width, th = ts.tile_height, m = ts.margin, sp = ts.spacing;
    if (tw <= 0 || th <= 0 || tw + sp <= 0 || th + sp <= 0) return 0;
    if (columns <= 0) columns = int((image_w - 2 * m + sp) / (tw + sp));
    if (columns <= 0) return 0;
    // A column (row) k fits when m + k·(tw + sp) + tw is within the image.
    const auto fitting = [&](int64_t side, int64_t t) { return side < m + t ? 0 : (side - m - t) / (t + sp) + 1; };
    const int64_t cols = fitting(image_w, tw), rows = fitting(image_h, th);
    if (rows == 0) return 0;
    return uint32_t(std::min<int64_t>(cols < columns ? cols : rows * columns, UINT32_MAX));
}

bool Tileset::tile_solid(uint32_t local_id) const {
    const TileInfo* t = tile(local_id);
    if (!t) return false;
    if (t->has_collision_shapes) return true;
    for (const char* name : {"solid", "collision", "collides"})
        if (const Property* p = find_property(t->properties, name); p && property_is_true(*p))
            return true;
    return false;
}

bool Tileset::tile_one_way(uint32_t local_id) const {
    const TileInfo* t = tile(local_id);
    const Property* p = t ? find_property(t->properties, "one-way") : nullptr;
    return p && property_is_true(*p);
}

uint32_t TileLayer::raw_gid(int64_t col, int64_t row) const {
    col -= origin_col;
    row -= origin_row;
    if (col < 0 || row < 0 || col >= width || row >= height) return 0;
    return cells[static_cast<size_t>(row * width + col)];
}

const Tileset* Tilemap::tileset_for(uint32_t gid) const {
    gid &= kGidMask;
    if (gid == 0) return nullptr;
    const auto it = std::upper_bound(tilesets.begin(), tilesets.end(), gid,
                                     [](uint32_t g, const Tileset& t) { return g < t.firstgid; });
    return it == tilesets.begin() ? nullptr : &*std::prev(it);
}

bool Tilemap::gid_solid(uint32_t gid) const {
    gid &= kGidMask;
    if (gid == 0) return false;
    const Tileset* ts = tileset_for(gid);  // looked up once: solid_grid asks every cell
    // A gid beyond every tileset (loaded with a warning) is drawn as missing
    // and never solid, whatever the layer or the script say.
    if (!known_in(*this, ts, gid)) return false;
    for (const uint32_t s : extra_solid_gids)
        if ((s & kGidMask) == gid) return true;
    return ts && ts->tile_solid(gid - ts->firstgid);
}

bool Tilemap::cell_solid(int64_t col, int64_t row) const {
    const CellPart p = cell_part(col, row);
    return p.kind == kSolidCell || (p.kind == kShapedCell && !p.shape.one_way);
}

bool Tilemap::gid_one_way(uint32_t gid) const {
    gid &= kGidMask;
    if (gid == 0 || gid_solid(gid)) return false;
    for (const uint32_t s : extra_one_way_gids)
        if ((s & kGidMask) == gid) return true;
    const Tileset* ts = tileset_for(gid);
    return ts && ts->tile_one_way(gid - ts->firstgid);
}

bool Tilemap::cell_one_way(int64_t col, int64_t row) const {
    const CellPart p = cell_part(col, row);
    return p.kind == kOneWayCell || (p.kind == kShapedCell && p.shape.one_way);
}

namespace {

bool listed(const std::vector<uint32_t>& gids, uint32_t gid) {
    return std::any_of(gids.begin(), gids.end(), [&](uint32_t g) { return (g & kGidMask) == gid; });
}

bool property_solid(const TileInfo& t) {
    for (const char* name : {"solid", "collision", "collides"})
        if (const Property* p = find_property(t.properties, name); p && property_is_true(*p)) return true;
    return false;
}

CellPart whole_or_shape(const TileSolidPart& part, bool one_way) {
    CellPart c;
    if (part.empty) return c;
    if (part.whole) {
        c.kind = one_way ? kOneWayCell : kSolidCell;
    } else {
        c.kind = kShapedCell;
        c.shape = part.shape;
        c.shape.one_way = one_way;
    }
    return c;
}

// Cells of one map over its layers: the rule of Tilemap::cell_part.
struct Composer {
    bool solid = false, one_way = false;
    bool has_solid_shape = false, has_one_way_shape = false;
    CellShape solid_shape, one_way_shape;

    void add(const CellPart& p) {
        if (p.kind == kSolidCell) solid = true;
        if (p.kind == kOneWayCell) one_way = true;
        if (p.kind != kShapedCell) return;
        bool& has = p.shape.one_way ? has_one_way_shape : has_solid_shape;
        CellShape& kept = p.shape.one_way ? one_way_shape : solid_shape;
        bool& whole = p.shape.one_way ? one_way : solid;
        if (has && !(kept == p.shape)) whole = true;
        has = true;
        kept = p.shape;
    }
    CellPart result() const {
        CellPart c;
        if (solid) c.kind = kSolidCell;
        else if (has_solid_shape) c.kind = kShapedCell, c.shape = solid_shape;
        else if (one_way) c.kind = kOneWayCell;
        else if (has_one_way_shape) c.kind = kShapedCell, c.shape = one_way_shape;
        return c;
    }
};

}  // namespace

CellPart Tilemap::gid_part(uint32_t raw) const {
    const uint32_t gid = raw & kGidMask, flips = raw & ~kGidMask;
    CellPart none;
    if (gid == 0) return none;
    const Tileset* ts = tileset_for(gid);
    if (!known_in(*this, ts, gid)) return none;
    if (listed(extra_solid_gids, gid)) return {kSolidCell, {}};
    for (const GidShape& s : extra_shapes)
        if ((s.gid & kGidMask) == gid)
            return whole_or_shape(tile_solid_part({s.object}, tile_width, tile_height, flips),
                                  listed(extra_one_way_gids, gid));
    const TileInfo* t = ts ? ts->tile(gid - ts->firstgid) : nullptr;
    if (t && property_solid(*t)) return {kSolidCell, {}};
    if (t && t->has_collision_shapes) {
        const bool one_way = ts->tile_one_way(gid - ts->firstgid);
        // Shapes are in the tileset's tile px: a tileset whose tiles are not
        // the map's cells keeps the whole cell.
        if (ts->tile_width != tile_width || ts->tile_height != tile_height) return {one_way ? kOneWayCell : kSolidCell, {}};
        return whole_or_shape(tile_solid_part(t->objects, tile_width, tile_height, flips), one_way);
    }
    if (listed(extra_one_way_gids, gid) || (ts && ts->tile_one_way(gid - ts->firstgid))) return {kOneWayCell, {}};
    return none;
}

namespace {

// A cell's part over its layers, with `part_of(raw)` giving a gid's part in
// a layer whose tiles decide: gid_part itself, or a table of the parts
// already found (a shape is classified once per gid and flip, not per cell).
template <class PartOf>
CellPart compose_cell(const Tilemap& map, int64_t col, int64_t row, PartOf&& part_of) {
    Composer c;
    for (const TileLayer& layer : map.layers) {
        if (layer.solidity == LayerSolidity::None) continue;
        const uint32_t raw = layer.raw_gid(col, row);
        if ((raw & kGidMask) == 0) continue;
        if (layer.solidity == LayerSolidity::All) {
            if (map.gid_known(raw)) c.add({kSolidCell, {}});
            continue;
        }
        c.add(part_of(raw));
    }
    return c.result();
}

}  // namespace

CellPart Tilemap::cell_part(int64_t col, int64_t row) const {
    return compose_cell(*this, col, row, [&](uint32_t raw) { return gid_part(raw); });
}

bool Tilemap::gid_known(uint32_t gid) const {
    gid &= kGidMask;
    return gid == 0 || known_in(*this, tileset_for(gid), gid);
}

void Tilemap::set_gid(size_t layer, int64_t col, int64_t row, uint32_t gid) {
    if (layer >= layers.size()) throw std::out_of_range("tilemap: no tile layer " + std::to_string(layer));
    TileLayer& l = layers[layer];
    const int64_t c = col - l.origin_col, r = row - l.origin_row;
    if (c < 0 || r < 0 || c >= l.width || r >= l.height)
        throw std::out_of_range("tilemap: cell outside the layer");
    l.cells[static_cast<size_t>(r * l.width + c)] = gid;
}

std::string tileset_image_path(const Tileset& ts, const std::string& image) {
    if (ts.image_dir.empty() || std::filesystem::path(image).is_absolute()) return image;
    return (std::filesystem::path(ts.image_dir) / image).string();
}

std::string layer_image_path(const Tilemap& map, const std::string& image) {
    const std::filesystem::path p(image);
    if (p.is_absolute() || map.path.empty()) return image;
    return (std::filesystem::path(map.path).parent_path() / p).string();
}

void set_tile(Tilemap& map, TileGrid& grid, size_t layer, int64_t col, int64_t row, uint32_t gid) {
    if (!map.gid_known(gid))
        throw std::invalid_argument("set_tile: gid " + std::to_string(gid & kGidMask) +
                                    " belongs to none of the map's tilesets");
    if (grid.clip_cols({col, col}).empty() || grid.clip_rows({row, row}).empty())
        throw std::out_of_range("set_tile: cell outside the grid");
    const uint32_t old = layer < map.layers.size() ? map.layers[layer].raw_gid(col, row) : 0;
    map.set_gid(layer, col, row, gid);
    const CellPart now = map.cell_part(col, row);
    try {
        if (now.kind == kShapedCell) grid.set_shape(col, row, now.shape);
        else grid.set_cell(col, row, now.kind);
    } catch (...) {  // a grid out of room for shapes: leave both as they were
        map.set_gid(layer, col, row, old);
        throw;
    }
}

TileGrid Tilemap::solid_grid() const {
    Bounds b;
    for (const TileLayer& l : layers) b.add(l);
    const int64_t cols = b.col1 - b.col0, rows = b.row1 - b.row0;
    if (cols > std::numeric_limits<int>::max() || rows > std::numeric_limits<int>::max())
        throw std::length_error("tilemap: solid grid wider or taller than an int");
    const size_t n = static_cast<size_t>(cols) * static_cast<size_t>(rows);
    std::vector<uint8_t> solid(n, 0);
    // Cells that a shaped tile touched are composed again (compose_cell),
    // which knows every rule; the rest take the fast way below.
    std::vector<size_t> shaped;
    // Layer by layer rather than cell_part per cell: one pass over each
    // layer's own cells, with each distinct raw gid's part looked up once.
    std::unordered_map<uint32_t, CellPart> gid_cache;
    const auto cached_part = [&](uint32_t raw) {
        auto [it, fresh] = gid_cache.try_emplace(raw);
        if (fresh) it->second = gid_part(raw);
        return it->second;
    };
    constexpr uint8_t kShapeSeen = 0x80;  // marks a cell in `solid` for `shaped`
    for (const TileLayer& l : layers) {
        if (l.solidity == LayerSolidity::None) continue;
        for (int r = 0; r < l.height; ++r) {
            for (int c = 0; c < l.width; ++c) {
                const uint32_t raw = l.cells[static_cast<size_t>(r) * l.width + c];
                if ((raw & kGidMask) == 0) continue;
                uint8_t kind;
                if (l.solidity == LayerSolidity::All) {
                    kind = gid_known(raw) ? kSolidCell : kEmptyCell;  // unknown gids are never solid
                } else {
                    kind = cached_part(raw).kind;
                }
                if (kind == kEmptyCell) continue;
                const int64_t gc = l.origin_col + c - b.col0, gr = l.origin_row + r - b.row0;
                const size_t i = static_cast<size_t>(gr * cols + gc);
                uint8_t& cell = solid[i];
                if (kind == kShapedCell) {
                    if (!(cell & kShapeSeen)) shaped.push_back(i);
                    cell |= kShapeSeen;
                } else if ((cell & ~kShapeSeen) != kSolidCell) {
                    cell = static_cast<uint8_t>((cell & kShapeSeen) | kind);  // a solid layer wins over a one-way one
                }
            }
        }
    }
    std::vector<std::pair<size_t, CellPart>> parts;
    for (const size_t i : shaped) {
        const CellPart p = compose_cell(*this, b.col0 + static_cast<int64_t>(i % static_cast<size_t>(cols)),
                                        b.row0 + static_cast<int64_t>(i / static_cast<size_t>(cols)), cached_part);
        solid[i] = p.kind == kShapedCell ? kEmptyCell : p.kind;
        if (p.kind == kShapedCell) parts.push_back({i, p});
    }
    TileGrid grid(static_cast<int>(cols), static_cast<int>(rows), tile_width, tile_height, std::move(solid),
                  b.col0, b.row0);
    for (const auto& [i, p] : parts)
        grid.set_shape(b.col0 + static_cast<int64_t>(i % static_cast<size_t>(cols)),
                       b.row0 + static_cast<int64_t>(i / static_cast<size_t>(cols)), p.shape);
    return grid;
}

MapError::MapError(const std::string& file, int line, const std::string& message)
    : std::runtime_error(where(file, line) + ": " + message), file_(file), line_(line) {}

Tilemap make_tilemap(int width, int height, int tile_w, int tile_h, std::vector<uint32_t> gids,
                     std::vector<uint32_t> solid_gids, int64_t max_cells, std::vector<uint32_t> one_way_gids,
                     std::vector<GidShape> shapes) {
    if (const std::string p = map_size_problem(width, height, tile_w, tile_h, max_cells); !p.empty())
        throw std::invalid_argument("make_tilemap: " + p);
    if (gids.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
        throw std::invalid_argument("make_tilemap: " + std::to_string(gids.size()) +
                                    " gids for a " + std::to_string(width) + "x" +
                                    std::to_string(height) + " map");
    for (const GidShape& s : shapes)
        if (const TileSolidPart p = tile_solid_part({s.object}, tile_w, tile_h, 0); !p.problem.empty())
            throw std::invalid_argument("make_tilemap: the shape of gid " + std::to_string(s.gid & kGidMask) +
                                        ": " + p.problem);
    Tilemap map;
    map.width = width;
    map.height = height;
    map.tile_width = tile_w;
    map.tile_height = tile_h;
    TileLayer layer;
    layer.name = "tiles";
    layer.width = width;
    layer.height = height;
    layer.cells = std::move(gids);
    map.layers.push_back(std::move(layer));
    // No tilesets: extra_solid_gids alone decides, exactly as the caller listed.
    map.extra_solid_gids = std::move(solid_gids);
    map.extra_one_way_gids = std::move(one_way_gids);
    map.extra_shapes = std::move(shapes);
    return map;
}

}  // namespace ds
