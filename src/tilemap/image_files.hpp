// The pictures a loaded map names, checked when it loads rather than when a
// window first draws them: a headless run, and every test without a golden
// frame, would otherwise pass on a map that cannot be drawn. Only whether
// each file can be opened is checked (it exists, is a regular file, may be
// read); decoding is the renderer's (src/render/tile_art.*), as src/ has no
// SDL.
#pragma once
#include <string>

#include "map_build.hpp"
#include "tilemap.hpp"

namespace ds::build {

// Where the renderer opens a picture `image` written in tileset `ts`: the
// tileset's folder (image_dir) joined to it, unless it is absolute or the
// tileset was made in memory.
std::string tileset_image_path(const Tileset& ts, const std::string& image);
// Where it opens an image layer's `image`: the map's folder joined to it.
std::string layer_image_path(const Tilemap& map, const std::string& image);

// Every tileset's image, every image-collection tile's image and every
// image layer's image of `map` (nested in groups too), each distinct file
// opened once. One that cannot be opened is a warning on the map naming
// the tileset (or layer), the file and the reason, one per tileset or layer
// (an image collection counts the rest of its tiles whose images fail); a
// strict load refuses the map with a MapError instead.
void check_image_files(const LoadState& s, Tilemap& map);

}  // namespace ds::build
