// SPDX-License-Identifier: MIT
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

// Every tileset's image, every image-collection tile's image and every
// image layer's image of `map` (nested in groups too), each distinct file
// opened once. One that cannot be opened is a warning on the map naming
// the tileset (or layer), the file and the reason, one per tileset or layer
// (an image collection counts the rest of its tiles whose images fail); a
// strict load refuses the map with a MapError instead.
void check_image_files(const LoadState& s, Tilemap& map);

}  // namespace ds::build
