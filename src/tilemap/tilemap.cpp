#include "tilemap.hpp"

#include <algorithm>
#include <cctype>
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
    for (const TileLayer& layer : layers) {
        if (layer.solidity == LayerSolidity::None) continue;
        const uint32_t gid = layer.raw_gid(col, row) & kGidMask;
        if (gid == 0) continue;
        if (layer.solidity == LayerSolidity::All ? gid_known(gid) : gid_solid(gid)) return true;
    }
    return false;
}

bool Tilemap::gid_one_way(uint32_t gid) const {
    gid &= kGidMask;
    if (gid == 0 || gid_solid(gid)) return false;
    for (const uint32_t s : extra_one_way_gids)
        if ((s & kGidMask) == gid) return true;
    const Tileset* ts = tileset_for(gid);
    return ts && ts->tile_one_way(gid - ts->firstgid);
}

bool Tilemap::cell_one_way(int64_t col, int64_t row) const { return cell_kind(col, row) == kOneWayCell; }

uint8_t Tilemap::cell_kind(int64_t col, int64_t row) const {
    if (cell_solid(col, row)) return kSolidCell;
    for (const TileLayer& layer : layers)
        if (layer.solidity == LayerSolidity::FromTiles && gid_one_way(layer.raw_gid(col, row))) return kOneWayCell;
    return kEmptyCell;
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

void set_tile(Tilemap& map, TileGrid& grid, size_t layer, int64_t col, int64_t row, uint32_t gid) {
    if (!map.gid_known(gid))
        throw std::invalid_argument("set_tile: gid " + std::to_string(gid & kGidMask) +
                                    " belongs to none of the map's tilesets");
    if (grid.clip_cols({col, col}).empty() || grid.clip_rows({row, row}).empty())
        throw std::out_of_range("set_tile: cell outside the grid");
    map.set_gid(layer, col, row, gid);
    grid.set_cell(col, row, map.cell_kind(col, row));
}

TileGrid Tilemap::solid_grid() const {
    Bounds b;
    for (const TileLayer& l : layers) b.add(l);
    const int64_t cols = b.col1 - b.col0, rows = b.row1 - b.row0;
    if (cols > std::numeric_limits<int>::max() || rows > std::numeric_limits<int>::max())
        throw std::length_error("tilemap: solid grid wider or taller than an int");
    std::vector<uint8_t> solid(static_cast<size_t>(cols) * static_cast<size_t>(rows), 0);
    // Layer by layer rather than cell_solid per cell: one pass over each
    // layer's own cells, with each distinct gid's metadata looked up once.
    // gid → the cell kind its tile metadata gives, or kUnknownGid.
    constexpr uint8_t kUnknownGid = 0xFF;
    std::unordered_map<uint32_t, uint8_t> gid_cache;
    for (const TileLayer& l : layers) {
        if (l.solidity == LayerSolidity::None) continue;
        for (int r = 0; r < l.height; ++r) {
            for (int c = 0; c < l.width; ++c) {
                const uint32_t gid = l.cells[static_cast<size_t>(r) * l.width + c] & kGidMask;
                if (gid == 0) continue;
                auto [it, fresh] = gid_cache.try_emplace(gid, kUnknownGid);
                if (fresh && gid_known(gid))
                    it->second = gid_solid(gid) ? kSolidCell : gid_one_way(gid) ? kOneWayCell : kEmptyCell;
                // Unknown gids are never solid, even in a solid layer.
                const uint8_t kind = it->second == kUnknownGid           ? kEmptyCell
                                     : l.solidity == LayerSolidity::All ? kSolidCell
                                                                        : it->second;
                if (kind == kEmptyCell) continue;
                const int64_t gc = l.origin_col + c - b.col0, gr = l.origin_row + r - b.row0;
                uint8_t& cell = solid[static_cast<size_t>(gr * cols + gc)];
                if (cell != kSolidCell) cell = kind;  // a solid layer wins over a one-way one
            }
        }
    }
    return TileGrid(static_cast<int>(cols), static_cast<int>(rows), tile_width, tile_height,
                    std::move(solid), b.col0, b.row0);
}

MapError::MapError(const std::string& file, int line, const std::string& message)
    : std::runtime_error(where(file, line) + ": " + message), file_(file), line_(line) {}

Tilemap make_tilemap(int width, int height, int tile_w, int tile_h, std::vector<uint32_t> gids,
                     std::vector<uint32_t> solid_gids, int64_t max_cells, std::vector<uint32_t> one_way_gids) {
    if (const std::string p = map_size_problem(width, height, tile_w, tile_h, max_cells); !p.empty())
        throw std::invalid_argument("make_tilemap: " + p);
    if (gids.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
        throw std::invalid_argument("make_tilemap: " + std::to_string(gids.size()) +
                                    " gids for a " + std::to_string(width) + "x" +
                                    std::to_string(height) + " map");
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
    return map;
}

}  // namespace ds
