// SPDX-License-Identifier: MIT
// The pictures a map names, checked when it loads (issue 46): a tileset's
// image, an image-collection tile's, an image layer's. A missing or
// unreadable one is a warning naming the tileset (or layer) and the file, or
// a strict load's error; the loader never decodes them.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tilemap/tilemap.hpp"

using namespace ds;

namespace {

// A folder of its own under the system's temporary one, removed with all it holds.
struct TempDir {
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "ds-images-XXXXXX").string();
        path = mkdtemp(pattern.data());
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    std::string file(const std::string& name, const std::string& text = "stand-in") const {
        const std::string p = path + "/" + name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    std::string path;
};

// A map with an atlas tileset (atlas.png), an image collection (rock.png,
// bush.png, tree.png) and an image layer (sky.png) inside a group.
constexpr const char* kMap = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="2" height="1" tilewidth="8" tileheight="8">
 <tileset firstgid="1" name="atlas" tilewidth="8" tileheight="8" tilecount="2" columns="2">
  <image source="atlas.png" width="16" height="8"/>
 </tileset>
 <tileset firstgid="3" name="props" tilewidth="8" tileheight="8" tilecount="3" columns="0">
  <tile id="0"><image source="rock.png" width="8" height="8"/></tile>
  <tile id="1"><image source="bush.png" width="8" height="8"/></tile>
  <tile id="2"><image source="tree.png" width="8" height="8"/></tile>
 </tileset>
 <layer id="1" name="ground" width="2" height="1"><data encoding="csv">1,3</data></layer>
 <group id="2" name="back">
  <imagelayer id="3" name="sky"><image source="sky.png" width="16" height="8"/></imagelayer>
 </group>
</map>
)";

Tilemap load(const std::string& path, bool strict = false) {
    LoadOptions options;
    options.strict = strict;
    return load_tilemap(path, options);
}

std::string refusal(const std::string& path) {
    try {
        load(path, true);
    } catch (const MapError& e) {
        return e.what();
    }
    return "(loaded without error)";
}

}  // namespace

TEST_SUITE("image-files") {

TEST_CASE("a map whose pictures are all there loads without a warning, strict too") {
    TempDir d;
    for (const char* image : {"atlas.png", "rock.png", "bush.png", "tree.png", "sky.png"}) d.file(image);
    const std::string map = d.file("map.tmx", kMap);
    CHECK(load(map).warnings.empty());
    CHECK(load(map, true).warnings.empty());
}

TEST_CASE("a missing picture is a warning naming the tileset or layer and the file, one per tileset") {
    TempDir d;
    d.file("bush.png");
    const std::string map = d.file("map.tmx", kMap);
    const Tilemap m = load(map);
    REQUIRE(m.warnings.size() == 3);
    CHECK(m.warnings[0] == map + ": tileset 'atlas': image '" + d.path +
                               "/atlas.png' cannot be opened: No such file or directory; its tiles cannot be drawn");
    CHECK(m.warnings[1] == map + ": tileset 'props', tile 0: image '" + d.path +
                               "/rock.png' cannot be opened: No such file or directory (and 1 more of its tiles' "
                               "images); its tiles cannot be drawn");
    CHECK(m.warnings[2] == map + ": image layer 'sky': image '" + d.path +
                               "/sky.png' cannot be opened: No such file or directory; the layer cannot be drawn");
    // Loaded all the same: the cells are there, for a headless run.
    CHECK(m.layers[0].raw_gid(1, 0) == 3);
    CHECK(refusal(map) == map + ": tileset 'atlas': image '" + d.path +
                              "/atlas.png' cannot be opened: No such file or directory");
}

TEST_CASE("a folder or a FIFO named as a picture is refused without being read") {
    TempDir d;
    for (const char* image : {"rock.png", "bush.png", "tree.png"}) d.file(image);
    std::filesystem::create_directory(d.path + "/atlas.png");
    REQUIRE(mkfifo((d.path + "/sky.png").c_str(), 0600) == 0);
    const std::string map = d.file("map.tmx", kMap);
    const Tilemap m = load(map);  // a FIFO without a writer: this would hang if opened blocking
    REQUIRE(m.warnings.size() == 2);
    CHECK(m.warnings[0] == map + ": tileset 'atlas': image '" + d.path +
                               "/atlas.png' cannot be opened: is a directory; its tiles cannot be drawn");
    CHECK(m.warnings[1] == map + ": image layer 'sky': image '" + d.path +
                               "/sky.png' cannot be opened: is not a regular file (a FIFO); the layer cannot be drawn");
    CHECK(refusal(map) == map + ": tileset 'atlas': image '" + d.path + "/atlas.png' cannot be opened: is a directory");
}

TEST_CASE("a picture that may not be read is named with the system's reason") {
    TempDir d;
    for (const char* image : {"atlas.png", "rock.png", "bush.png", "sky.png"}) d.file(image);
    const std::string tree = d.file("tree.png");
    REQUIRE(chmod(tree.c_str(), 0) == 0);
    const std::string map = d.file("map.tmx", kMap);
    if (geteuid() == 0) {  // root reads any file: nothing to refuse
        CHECK(load(map).warnings.empty());
        return;
    }
    const Tilemap m = load(map);
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == map + ": tileset 'props', tile 2: image '" + tree +
                               "' cannot be opened: Permission denied; its tiles cannot be drawn");
}

TEST_CASE("an external tileset's pictures are found beside it, and it is named by its source") {
    TempDir d;
    std::filesystem::create_directory(d.path + "/sets");
    d.file("sets/terrain.tsx", R"(<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" name="terrain" tilewidth="8" tileheight="8" tilecount="2" columns="2">
 <image source="../art/terrain.png" width="16" height="8"/>
</tileset>
)");
    const std::string map = d.file("map.tmx", R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" width="1" height="1" tilewidth="8" tileheight="8">
 <tileset firstgid="1" source="sets/terrain.tsx"/>
 <layer id="1" name="ground" width="1" height="1"><data encoding="csv">1</data></layer>
</map>
)");
    const Tilemap m = load(map);
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == map + ": tileset 'terrain' (sets/terrain.tsx): image '" + d.path +
                               "/sets/../art/terrain.png' cannot be opened: No such file or directory; its tiles "
                               "cannot be drawn");
    std::filesystem::create_directory(d.path + "/art");
    d.file("art/terrain.png");
    CHECK(load(map, true).warnings.empty());
}

}  // TEST_SUITE
