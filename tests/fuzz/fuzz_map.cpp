// SPDX-License-Identifier: MIT
// libFuzzer target for the TMX/TSX loader (ds::load_tilemap). Built twice:
// as `tmx` the input is the map, which may name the fixed tileset below under
// any of the names the seed maps use; as `tsx` (DS_FUZZ_TSX) the input is the
// tileset a fixed map names. A MapError is the loader refusing the input, as
// it should; anything else escaping (another exception, a crash, a sanitizer
// report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scratch_dir.hpp"
#include "tilemap/tilemap.hpp"

namespace {

// Solid by property, by collision shapes, not solid, and a typed tile: each
// rule of semantics §7 that reads a tileset.
constexpr std::string_view kTileset = R"(<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" name="fixed" tilewidth="16" tileheight="16" tilecount="8" columns="4">
 <image source="fixed.png" width="64" height="32"/>
 <tile id="0"><properties><property name="solid" type="bool" value="true"/></properties></tile>
 <tile id="1"><objectgroup><object id="1" x="0" y="8" width="16" height="8"/></objectgroup></tile>
 <tile id="2" class="spikes"><properties><property name="collision" value="TRUE"/></properties></tile>
 <tile id="3"><properties><property name="solid" type="bool" value="false"/></properties></tile>
</tileset>
)";

// The tileset names the seed maps (tests/data/maps, demo/maps) refer to.
constexpr std::string_view kTilesetNames[] = {"fixed.tsx", "tilesets/terrain.tsx", "demo-tiles.tsx",
                                              "sprites.tsx", "tiles.tsx"};

// Two tilesets (the fuzzed one external, one embedded after it), a CSV layer
// using gids of both with flip bits, and an infinite-style offset object.
constexpr std::string_view kMap = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="4" height="3" tilewidth="16" tileheight="16" infinite="0">
 <tileset firstgid="1" source="fuzz.tsx"/>
 <tileset firstgid="100" name="inline" tilewidth="16" tileheight="16" tilecount="2" columns="2">
  <tile id="1"><properties><property name="solid" type="bool" value="true"/></properties></tile>
 </tileset>
 <layer id="1" name="ground" width="4" height="3">
  <data encoding="csv">1,2,3,4,5,6,7,8,2147483649,100,101,0</data>
 </layer>
 <objectgroup id="2" name="things"><object id="1" x="8" y="8" width="16" height="16" gid="2"/></objectgroup>
</map>
)";

#ifdef DS_FUZZ_TSX
constexpr const char* kLabel = "tsx";
#else
constexpr const char* kLabel = "tmx";
#endif

// The folder, holding the fixed files from the first call on.
const ds::fuzz::ScratchDir& scratch() {
    static const ds::fuzz::ScratchDir dir(kLabel);
    static const bool filled = [] {
#ifdef DS_FUZZ_TSX
        dir.write("map.tmx", kMap);
#else
        for (std::string_view name : kTilesetNames) dir.write(name, kTileset);
#endif
        return true;
    }();
    (void)filled;
    return dir;
}

// Cells asked of both the map and its grid per input: all of any map a
// mutation makes from the seeds, while a legal map of 2^26 cells (the
// loader's bound) still takes well under the run's -timeout.
constexpr int64_t kCellsChecked = int64_t{1} << 16;

// What a game does with a loaded map: the physics grid, per-gid lookups,
// and layer cells asked through both the map and the grid.
void use(const ds::Tilemap& map) {
    const ds::TileGrid grid = map.solid_grid();
    int64_t budget = kCellsChecked;
    for (const ds::TileLayer& layer : map.layers)
        for (int64_t i = 0; i < int64_t{layer.width} * layer.height && budget > 0; ++i, --budget) {
            const int64_t col = layer.origin_col + i % layer.width, row = layer.origin_row + i / layer.width;
            const uint32_t gid = layer.raw_gid(col, row);
            if (const ds::Tileset* ts = map.tileset_for(gid & ds::kGidMask))
                (void)ts->tile((gid & ds::kGidMask) - ts->firstgid);
            if (map.cell_kind(col, row) != grid.cell(col, row)) __builtin_trap();  // the grid must say what the map says
            if (const ds::CellShape* s = grid.shape(col, row); s && !(*s == map.cell_part(col, row).shape))
                __builtin_trap();
        }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
#ifdef DS_FUZZ_TSX
    scratch().write("fuzz.tsx", bytes);
    const std::string path = scratch().path() + "/map.tmx";
#else
    const std::string path = scratch().write("map.tmx", bytes);
#endif
    try {
        use(ds::load_tilemap(path, {1, 5}));
    } catch (const ds::MapError&) {
        // refused, as malformed input should be
    }
    return 0;
}
