// SPDX-License-Identifier: MIT
// Maps built to exhaust, hang or confuse the loader (issue 19): each ends in
// a MapError naming the file, the line and the value, in bounded time and
// memory (the suite finishing shows the bound). The maps live in
// tests/data/maps/hostile and are written by tests/data/make_hostile_maps.py;
// FIFOs and large inputs are made here, in a temporary directory.
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tilemap/decode.hpp"
#include "tilemap/tilemap.hpp"

namespace {

using namespace ds;

std::string hostile(const std::string& name) {
    return std::string(DS_TEST_DATA) + "/maps/hostile/" + name;
}
std::string map_path(const std::string& rel) { return std::string(DS_TEST_DATA) + "/maps/" + rel; }

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

struct Failure {
    std::string what, file;
    int line = -1;
};

Failure failure_of(const std::string& path, const MapLimits& limits = {}) {
    try {
        // Strict: a gid beyond every tileset is the error these cases expect.
        LoadOptions options;
        options.limits = limits;
        options.strict = true;
        load_tilemap(path, options);
    } catch (const MapError& e) {
        return {e.what(), e.file(), e.line()};
    }
    return {"(loaded without error)", "", -1};
}

// A directory of its own under the system's temporary one, removed at the end.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        std::string templ = (std::filesystem::temp_directory_path() / "ds-hostile-XXXXXX").string();
        REQUIRE(mkdtemp(templ.data()) != nullptr);
        path = templ;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        const std::string p = (path / name).string();
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
};

// make_maps.py's small_map: the tileset on line 3, the layer on 4, its data on 5.
std::string small_map(const std::string& data, const std::string& tileset) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<map version=\"1.10\" orientation=\"orthogonal\" width=\"2\" height=\"2\" "
           "tilewidth=\"16\" tileheight=\"16\">\n " +
           tileset + "\n <layer id=\"1\" name=\"ground\" width=\"2\" height=\"2\">\n  " + data +
           "\n </layer>\n</map>\n";
}

// small_map with an object layer after the tile layer: its first object on line 8.
std::string map_with_object(const std::string& data, const std::string& tileset, const std::string& object) {
    std::string text = small_map(data, tileset);
    text.insert(text.rfind("</map>"), " <objectgroup id=\"2\" name=\"things\">\n  " + object + "\n </objectgroup>\n");
    return text;
}

const std::string kCsv = "<data encoding=\"csv\">1,2,3,4</data>";
const std::string kTileset =
    "<tileset firstgid=\"1\" name=\"t\" tilewidth=\"16\" tileheight=\"16\" tilecount=\"8\" "
    "columns=\"4\"/>";
const std::string kTsx =
    "<?xml version=\"1.0\"?>\n<tileset name=\"t\" tilewidth=\"16\" tileheight=\"16\" "
    "tilecount=\"8\" columns=\"4\"/>\n";

}  // namespace

TEST_SUITE("hostile-maps") {

TEST_CASE("each hostile map is refused, naming the file, the line and the value") {
    struct Case {
        const char* file;
        int line;
        std::string message;  // all of what() after "<file>:<line>: "
    };
    const std::string limit = "more than the loader's limit of 67108864 cells (max-cells)";
    const std::vector<Case> cases = {
        // 64 layers of 4096² zstd (4 GB decoded): the fifth is refused from
        // its attributes, before any layer is decoded.
        {"zstd_bomb.tmx", 16, "layer 'layer4' (16777216 cells) brings the map's tile layers to " + limit},
        {"zstd_overlong.tmx", 5,
         "layer 'ground': decompressed zstd data is larger than the 16 bytes the layer size allows"},
        {"zlib_overlong.tmx", 5,
         "layer 'ground': decompressed zlib data is larger than the 16 bytes the layer size allows"},
        {"gzip_overlong.tmx", 5,
         "layer 'ground': decompressed gzip data is larger than the 16 bytes the layer size allows"},
        {"zstd_short.tmx", 5, "layer 'ground' has 3 cells, expected 2x2 = 4"},
        {"tileset_urandom.tmx", 3,
         "cannot open tileset '/dev/urandom': is not a regular file (a character device)"},
        {"tileset_zero.tmx", 3,
         "cannot open tileset '/dev/zero': is not a regular file (a character device)"},
        {"zero_size.tmx", 2, "map size 0x0 is not positive"},
        {"layer_wider.tmx", 4, "layer 'ground' is 6x2 cells but the map is 2x2"},
        {"huge_tilewidth.tmx", 2, "tile size 2147483647x16 is larger than the limit of 16777216 px"},
        {"far_chunk.tmx", 5,
         "layer 'ground': column cells 2000000000 to 2000000000 of 16777216 px reach beyond 2^53 "
         "px, where coordinates stop being exact"},
        {"negative_firstgid.tmx", 3,
         "<tileset> attribute firstgid='-1' is not a non-negative integer"},
        {"huge_firstgid.tmx", 3, "<tileset> firstgid='4294967295' is out of range"},
        {"firstgid_past_gids.tmx", 3,
         "tileset 't' firstgid=268435450 with tilecount=8 runs past the largest gid 268435455"},
        {"duplicate_firstgid.tmx", 4,
         "<tileset> firstgid='1' is also the firstgid of the tileset on line 3"},
        {"flip_bits_gid.tmx", 5,
         "gid 268435455 (raw 0xFFFFFFFF) at cell (0, 0) of layer 'ground' is beyond every tileset"},
        {"gid_past_tilecount.tmx", 5,
         "gid 9 (raw 0x80000009) at cell (0, 0) of layer 'ground' is beyond every tileset"},
        {"base64_three_chars.tmx", 5,
         "layer 'ground': layer data is 2 bytes, not a whole number of 4-byte gids"},
        {"base64_junk.tmx", 5, "layer 'ground': invalid base64 character '%'"},
        {"csv_long.tmx", 5, "layer 'ground' has more than 4 cells, expected 2x2 = 4"},
        {"csv_short.tmx", 5, "layer 'ground' has 2 cells, expected 2x2 = 4"},
        {"csv_junk.tmx", 5, "layer 'ground': invalid CSV value '4;'"},
        {"xml_long.tmx", 5, "layer 'ground' has more than 4 cells, expected 2x2 = 4"},
        {"deep_groups.tmx", 35, "<group> nested more than 32 deep"},
        {"deeper_than_xml.tmx", 100,
         "malformed XML (XML_ELEMENT_DEPTH_EXCEEDED): Element nesting is too deep."},
        {"tileset_huge_image.tmx", 3,
         "<image> attribute width='2147483647' is larger than the limit of 65536 px"},
        {"tile_huge_image.tmx", 3,
         "<image> attribute height='99999999' is larger than the limit of 65536 px"},
        {"tileset_huge_spacing.tmx", 3,
         "<tileset> attribute spacing='2147483647' is larger than the limit of 65536 px"},
        {"tileset_huge_tile.tmx", 3,
         "tileset 't' tile size 2147483647x16 is larger than the limit of 16777216 px"},
        {"object_negative_height.tmx", 8, "<object> attribute height='-50' is negative"},
        {"polygon_bomb.tmx", 3,
         "tileset 't', tile 0: a collision shape of 6000 points, more than the 256 a shape may have"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.file);
        const Failure f = failure_of(hostile(c.file));
        CHECK(f.file == hostile(c.file));
        CHECK(f.line == c.line);
        CHECK(f.what == hostile(c.file) + ":" + std::to_string(c.line) + ": " + c.message);
    }
}

TEST_CASE("what the hostile maps leave legal still loads") {
    // A layer without width and height covers the map.
    const Tilemap sized = load_tilemap(hostile("layer_default_size.tmx"));
    CHECK(sized.layers.at(0).width == 3);
    CHECK(sized.layers.at(0).height == 2);
    // A .tsx naming itself as its source: the source is not followed.
    const Tilemap self = load_tilemap(hostile("tileset_self.tmx"));
    REQUIRE(self.tilesets.size() == 1);
    CHECK(self.tilesets[0].name == "self");
    CHECK(self.tilesets[0].tile_count == 8);
    // Overlapping chunks: the later wins, as the file lists them.
    const Tilemap chunks = load_tilemap(hostile("overlapping_chunks.tmx"));
    CHECK(chunks.layers.at(0).width == 16);
    CHECK(chunks.layers.at(0).cells.size() == 256u);
}

TEST_CASE("max_cells bounds the tile layers of a whole map, chunks included") {
    // layers.tmx: four 4x3 layers (48 cells); the fourth, 'hidden', is on line 46.
    CHECK(load_tilemap(map_path("layers.tmx"), {}, {.max_cells = 48}).layers.size() == 4);
    const Failure layers = failure_of(map_path("layers.tmx"), {.max_cells = 47});
    CHECK(layers.what == map_path("layers.tmx") +
                             ":46: layer 'hidden' (12 cells) brings the map's tile layers to more "
                             "than the loader's limit of 47 cells (max-cells)");
    // The header alone: a 6x4 map cannot hold 24 cells under 23.
    CHECK(failure_of(map_path("level_csv.tmx"), {.max_cells = 23}).what ==
          map_path("level_csv.tmx") + ":2: map size 6x4 is more than the max-cells limit of 23 cells");
    // infinite.tmx: ground's chunks span 8x4, overhang's 4x2: 40 cells, and
    // the solid grid over both 12x6, which the limit bounds too.
    CHECK(load_tilemap(map_path("infinite.tmx"), {}, {.max_cells = 72}).width == 12);
    CHECK(failure_of(map_path("infinite.tmx"), {.max_cells = 71}).what ==
          map_path("infinite.tmx") +
              ":2: the map's chunks span 12x6 cells, more than the loader's limit of 71 cells "
              "(max-cells)");
    CHECK(contains(failure_of(map_path("infinite.tmx"), {.max_cells = 39}).what,
                   "infinite.tmx:16: layer 'overhang' (8 cells) brings the map's tile layers to "
                   "more than the loader's limit of 39 cells (max-cells)"));
    // Three overlapping 16x16 chunks decode 768 cells for a 256-cell layer:
    // what is decoded counts, not only the block it lands in.
    CHECK(failure_of(hostile("overlapping_chunks.tmx"), {.max_cells = 600}).what ==
          hostile("overlapping_chunks.tmx") +
              ":5: chunk (0, 0) of layer 'ground' (16x16) brings the layer's chunks to more than "
              "the loader's limit of 600 cells (max-cells)");
}

TEST_CASE("only regular files are read: FIFOs, devices, directories") {
    const TempDir dir;
    const std::string fifo = (dir.path / "pipe.tsx").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string map =
        dir.write("m.tmx", small_map(kCsv, "<tileset firstgid=\"1\" source=\"pipe.tsx\"/>"));
    CHECK(failure_of(map).what ==
          map + ":3: cannot open tileset '" + fifo + "': is not a regular file (a FIFO)");
    CHECK(failure_of(fifo).what == fifo + ": cannot open map: is not a regular file (a FIFO)");
    CHECK(failure_of("/dev/zero").what ==
          "/dev/zero: cannot open map: is not a regular file (a character device)");
    CHECK(failure_of(dir.path.string()).what == dir.path.string() + ": cannot open map: is a directory");
}

TEST_CASE("max_bytes bounds the map and its tilesets together") {
    const TempDir dir;
    dir.write("t.tsx", kTsx);
    const std::string three_refs =
        "<tileset firstgid=\"1\" source=\"t.tsx\"/> <tileset firstgid=\"9\" source=\"t.tsx\"/> "
        "<tileset firstgid=\"17\" source=\"t.tsx\"/>";
    const std::string text = small_map(kCsv, three_refs);
    const std::string map = dir.write("m.tmx", text);
    const int64_t all = static_cast<int64_t>(text.size() + 3 * kTsx.size());
    CHECK(load_tilemap(map, {}, {.max_bytes = all}).tilesets.size() == 3);
    const Failure third = failure_of(map, {.max_bytes = all - 1});
    CHECK(third.what == map + ":3: cannot open tileset '" + (dir.path / "t.tsx").string() + "': is " +
                            std::to_string(kTsx.size()) + " bytes, more than the " +
                            std::to_string(kTsx.size() - 1) + " bytes max-bytes leaves");
    CHECK(failure_of(map, {.max_bytes = 10}).what ==
          map + ": cannot open map: is " + std::to_string(text.size()) +
              " bytes, more than the 10 bytes max-bytes allows");
    // A 1 GiB (sparse) file: refused from its size, nothing read.
    const std::string big = dir.write("big.tmx", "");
    std::filesystem::resize_file(big, std::uintmax_t{1} << 30);
    CHECK(failure_of(big).what ==
          big + ": cannot open map: is 1073741824 bytes, more than the 67108864 bytes max-bytes allows");
}

TEST_CASE("a long CSV is read no further than one value past the layer") {
    const TempDir dir;
    std::string csv;
    csv.reserve(10'000'000);
    while (csv.size() < 10'000'000) csv += "1,";
    const std::string map = dir.write("m.tmx", small_map("<data encoding=\"csv\">" + csv + "</data>", kTileset));
    CHECK(failure_of(map).what == map + ":5: layer 'ground' has more than 4 cells, expected 2x2 = 4");
    CHECK(tmx::parse_csv("1,2,3,x", 3) == std::vector<uint32_t>{1, 2, 3});
}

TEST_CASE("parse_tilemap reads a map from memory, as load_tilemap would") {
    const std::string text = small_map(kCsv, kTileset);
    const Tilemap m = parse_tilemap(text, "mem.tmx");
    CHECK(m.path == "mem.tmx");
    CHECK(m.layers.at(0).cells == std::vector<uint32_t>{1, 2, 3, 4});
    try {
        parse_tilemap(small_map("<data encoding=\"csv\">1,2</data>", kTileset), "mem.tmx");
        FAIL("loaded");
    } catch (const MapError& e) {
        CHECK(std::string(e.what()) == "mem.tmx:5: layer 'ground' has 2 cells, expected 2x2 = 4");
    }
    CHECK_THROWS_WITH_AS(parse_tilemap(text, "mem.tmx", {}, {.max_bytes = 10}),
                         ("mem.tmx: map is " + std::to_string(text.size()) +
                          " bytes, more than the 10 bytes max-bytes allows")
                             .c_str(),
                         MapError);
    CHECK_THROWS_WITH_AS(parse_tilemap(text, "mem.tmx", {}, {.max_cells = 0}),
                         "mem.tmx: max-cells 0 is not positive", MapError);
}

TEST_CASE("templates: FIFOs are refused, a template naming itself is not followed") {
    const TempDir dir;
    const std::string fifo = (dir.path / "pipe.tx").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string objects = "\n <objectgroup name=\"o\"><object id=\"1\" template=\"pipe.tx\"/></objectgroup>";
    const std::string map = dir.write("m.tmx", small_map(kCsv, kTileset + objects));
    CHECK(failure_of(map).what ==
          map + ":4: cannot open template '" + fifo + "': is not a regular file (a FIFO)");
    // Templates do not nest (Tiled's do not), so a loop cannot start.
    dir.write("loop.tx", "<template><object name=\"l\" template=\"loop.tx\"/></template>");
    const std::string looped = dir.write(
        "l.tmx", small_map(kCsv, kTileset + "\n <objectgroup name=\"o\"><object id=\"1\" template=\"loop.tx\"/></objectgroup>"));
    CHECK(load_tilemap(looped).object_layers.at(0).objects.at(0).name == "l");
}

TEST_CASE("class properties nest at most kMaxPropertyDepth deep") {
    const auto nested = [](int depth) {
        // Built in one pass: wrapping the string level by level is quadratic
        // (100 000 levels took 40 s).
        const std::string open = "<property name=\"c\" type=\"class\"><properties>",
                          close = "</properties></property>";
        std::string inner;
        inner.reserve(size_t(depth) * (open.size() + close.size()) + 64);
        for (int i = 0; i < depth; ++i) inner += open;
        inner += "<property name=\"leaf\" value=\"x\"/>";
        for (int i = 0; i < depth; ++i) inner += close;
        return small_map(kCsv, kTileset + "\n <properties>" + inner + "</properties>");
    };
    const Tilemap deepest = parse_tilemap(nested(kMaxPropertyDepth), "mem.tmx");
    const Property* p = &deepest.properties.at(0);
    for (int i = 1; i < kMaxPropertyDepth; ++i) p = &p->members.at(0);
    CHECK(p->members.at(0).name == "leaf");
    CHECK_THROWS_WITH_AS(parse_tilemap(nested(kMaxPropertyDepth + 1), "mem.tmx"),
                         "mem.tmx:4: properties nested more than 32 deep", MapError);
    // Far deeper than tinyxml2 parses: its own refusal, still a MapError.
    CHECK_THROWS_AS(parse_tilemap(nested(100000), "mem.tmx"), MapError);
}

TEST_CASE("make_tilemap keeps the loader's sizes") {
    CHECK_THROWS_WITH_AS(make_tilemap(1, 1, 2147483647, 16, {0}, {}),
                         "make_tilemap: tile size 2147483647x16 is larger than the limit of 16777216 px",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(make_tilemap(3, 2, 16, 16, {0, 0, 0, 0, 0, 0}, {}, 5),
                         "make_tilemap: map size 3x2 is more than the max-cells limit of 5 cells",
                         std::invalid_argument);
    CHECK(make_tilemap(3, 2, 16, 16, {0, 0, 0, 0, 0, 0}, {}, 6).width == 3);
    // 2^24 columns of 2^24 px end at 2^48 px: inside the exact range.
    CHECK(map_size_problem(1 << 24, 1, 1 << 24, 1, int64_t{1} << 40).empty());
    CHECK(extent_problem(-(int64_t{1} << 30), 1, 1 << 24, "column") ==
          "column cells -1073741824 to -1073741824 of 16777216 px reach beyond 2^53 px, where "
          "coordinates stop being exact");
}

TEST_CASE("objects are never upside down: a negative width or height is refused, at any size") {
    // The heap was corrupted from -20 px (the drawing index sized at no rows);
    // at -1000 the load failed naming no file.
    const TempDir dir;
    for (const char* h : {"-1", "-20", "-50", "-1000", "-1e300"}) {
        CAPTURE(h);
        const std::string object = std::string(R"(<object id="1" gid="1" x="0" y="32" width="16" height=")") + h + "\"/>";
        const std::string tmx = dir.write("o.tmx", map_with_object(kCsv, kTileset, object));
        CHECK(failure_of(tmx).what == tmx + ":8: <object> attribute height='" + h + "' is negative");
    }
    const std::string head = R"({"width":2,"height":2,"tilewidth":16,"tileheight":16,)"
                             R"("tilesets":[{"firstgid":1,"name":"t","tilewidth":16,"tileheight":16,"tilecount":8,"columns":4}],)";
    const std::string tmj = dir.write("o.tmj", head + R"("layers":[{"type":"objectgroup","name":"things","objects":[)"
                                                      R"({"id":1,"gid":1,"x":0,"y":32,"width":-20,"height":16}]}]})");
    CHECK(failure_of(tmj).what == tmj + ": layers[0].objects[0].width is the number -20, expected a number of at least 0");
    // Zero is a size (a point, or a tile object drawn at its tile's size).
    const std::string zero = dir.write(
        "z.tmx", map_with_object(kCsv, kTileset, R"(<object id="1" gid="1" x="0" y="32" width="0" height="0"/>)"));
    CHECK(load_tilemap(zero).object_layers.at(0).objects.at(0).height == 0);
}

TEST_CASE("collision shapes hold at most kMaxShapePoints points, and each is classified once") {
    const TempDir dir;
    // JSON too, naming the tileset and the tile.
    std::string points;
    for (int i = 0; i < 257; ++i) points += std::string(i ? "," : "") + R"({"x":0,"y":)" + std::to_string(i % 17) + "}";
    const std::string tmj = dir.write(
        "p.tmj", R"({"width":2,"height":2,"tilewidth":16,"tileheight":16,"tilesets":[{"firstgid":1,"name":"walls",)"
                 R"("tilewidth":16,"tileheight":16,"tilecount":8,"columns":4,"tiles":[{"id":3,"objectgroup":)"
                 R"({"type":"objectgroup","objects":[{"id":1,"x":0,"y":0,"polygon":[)" + points + "]}]}}]}]}");
    CHECK(failure_of(tmj).what ==
          tmj + ": tileset 'walls', tile 3: a collision shape of 257 points, more than the 256 a shape may have");
    // 256 points (a 1:2 ramp's three corners, the rest on its edges), on
    // every cell of a 1024 x 1024 map: classified once per gid and flip, so
    // it loads in about the time of a map of boxes (it was simplified again,
    // in quadratic time, for every cell).
    std::string outline = "0,16";
    for (int x = 1; x <= 16; ++x) outline += " " + std::to_string(x) + ",16";  // the floor: 17 points
    for (int k = 0; k < 238; ++k) outline += " 16,12";                       // the right side, over and over
    outline += " 16,8";  // the 256th: the ramp's top, whence the slant goes back to (0, 16)
    const int side = 1024;
    const std::string csv = std::string("<data encoding=\"csv\">") + [&] {
        std::string cells;
        cells.reserve(size_t(side) * side * 2);
        for (int i = 0; i < side * side; ++i) cells += i ? ",1" : "1";
        return cells;
    }() + "</data>";
    const std::string big = dir.write(
        "big.tmx", "<?xml version=\"1.0\"?>\n<map version=\"1.10\" orientation=\"orthogonal\" width=\"" +
                       std::to_string(side) + "\" height=\"" + std::to_string(side) +
                       "\" tilewidth=\"16\" tileheight=\"16\">\n <tileset firstgid=\"1\" name=\"t\" tilewidth=\"16\" "
                       "tileheight=\"16\" tilecount=\"8\" columns=\"4\"><tile id=\"0\"><objectgroup><object id=\"1\">"
                       "<polygon points=\"" + outline + "\"/></object></objectgroup></tile></tileset>\n"
                       " <layer id=\"1\" name=\"ground\">\n  " + csv + "\n </layer>\n</map>\n");
    const Tilemap map = load_tilemap(big);
    CHECK(map.tilesets.at(0).tiles.at(0).objects.at(0).points.size() == 256);
    const TileGrid grid = map.solid_grid();
    const CellPart part = map.cell_part(side - 1, side - 1);
    REQUIRE(part.kind == kShapedCell);
    CHECK(part.shape.cut == Cut::Floor);
    CHECK((part.shape.ax == 0 && part.shape.ay == 16 && part.shape.bx == 16 && part.shape.by == 8));
    CHECK(grid.cols() == side);
}

TEST_CASE("JSON maps: their tilesets, templates and project file keep every limit") {
    const TempDir dir;
    const std::string fifo = (dir.path / "pipe.tj").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string head = R"({"width":2,"height":2,"tilewidth":16,"tileheight":16,)";
    const std::string dev = dir.write("dev.tmj", head + R"("tilesets":[{"firstgid":1,"source":"/dev/zero"}]})");
    CHECK(failure_of(dev).what ==
          dev + ": cannot open tileset '/dev/zero': is not a regular file (a character device)");
    const std::string tpl = dir.write(
        "tpl.tmj", head + R"("layers":[{"type":"objectgroup","objects":[{"id":1,"template":"pipe.tj"}]}]})");
    CHECK(failure_of(tpl).what == tpl + ": cannot open template '" + fifo + "': is not a regular file (a FIFO)");
    // Sizes are refused from the header, before anything is allocated.
    const std::string huge = dir.write("huge.tmj", R"({"width":1000000,"height":1000000,"tilewidth":16,"tileheight":16,
        "layers":[{"type":"tilelayer","name":"a","width":1000000,"height":1000000,"data":[]}]})");
    CHECK(contains(failure_of(huge).what, "max-cells"));
    const std::string chunk = dir.write("chunk.tmj", head + R"("infinite":true,"layers":[{"type":"tilelayer","name":"a",
        "chunks":[{"x":0,"y":0,"width":100000,"height":100000,"data":[]}]}]})");
    CHECK(contains(failure_of(chunk).what, "max-cells"));
    const std::string inf = dir.write("inf.tmj", head + R"("layers":[{"type":"objectgroup","objects":[{"x":1e999}]}]})");
    CHECK(failure_of(inf).what == inf + ":1: malformed JSON at column 106: number overflow");
    // max-bytes counts the template and the project file too.
    const std::string tj = R"({"object":{"name":"t"}})";
    dir.write("t.tj", tj);
    const std::string text = head + R"("layers":[{"type":"objectgroup","objects":[{"id":1,"template":"t.tj"}]}]})";
    const std::string map = dir.write("m.tmj", text);
    const std::string project_text = R"({"propertyTypes":[]})";
    const std::string project = dir.write("p.tiled-project", project_text);
    LoadOptions options;
    options.project_path = project;
    options.limits.max_bytes = static_cast<int64_t>(text.size() + tj.size() + project_text.size());
    CHECK(load_tilemap(map, options).object_layers[0].objects[0].name == "t");
    options.limits.max_bytes -= 1;
    try {
        load_tilemap(map, options);
        FAIL("no error");
    } catch (const MapError& e) {
        CHECK(std::string(e.what()) == project + ": cannot open project file: is " +
                                           std::to_string(project_text.size()) + " bytes, more than the " +
                                           std::to_string(project_text.size() - 1) + " bytes max-bytes leaves");
    }
    // A project whose classes hold classes, two of each, 30 deep, is refused
    // after kMaxFilledMembers, not expanded into 2^30 members.
    std::string types;
    for (int i = 0; i < 30; ++i)
        types += (i ? "," : "") + std::string(R"({"name":"C)") + std::to_string(i) +
                 R"(","type":"class","members":[{"name":"a","type":"class","propertyType":"C)" +
                 std::to_string(i + 1) + R"(","value":{}},{"name":"b","type":"class","propertyType":"C)" +
                 std::to_string(i + 1) + R"(","value":{}}]})";
    types += R"(,{"name":"C30","type":"class","members":[]})";
    const std::string bomb = dir.write("bomb.tiled-project", R"({"propertyTypes":[)" + types + "]}");
    const std::string uses = dir.write("uses.tmj", head + R"("properties":[{"name":"p","type":"class","propertytype":"C0","value":{}}]})");
    options = {};
    options.project_path = bomb;
    try {
        load_tilemap(uses, options);
        FAIL("no error");
    } catch (const MapError& e) {
        CHECK(std::string(e.what()) ==
              bomb + ": filling class defaults needs more than 262144 members (kMaxFilledMembers)");
    }
}

}  // TEST_SUITE
