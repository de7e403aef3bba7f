// SPDX-License-Identifier: MIT
// What an image file says of itself before it is decoded: its format and
// its size, read from the first bytes of PNG, JPEG, GIF and BMP files (the
// formats Tiled's tilesets use and the renderer decodes). Pure arithmetic on
// bytes, no SDL: the loader checks the size against the bounds before any
// pixel is allocated, and a fuzz target feeds it anything.
#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace ds::render {

struct ImageHeader {
    const char* format = "";  // "PNG", "JPEG", "GIF" or "BMP"
    int64_t width = 0, height = 0;  // of the picture SDL_image decodes (a GIF's first image)
};

// The header of the image whose file is `bytes` (the loader reads it whole;
// a JPEG's size may come after its metadata, a GIF's image after its
// extensions). False, with `why` saying what is wrong, for a file that is
// none of the four formats, is cut short before its size, or declares a
// size that is not positive (a GIF: has no image SDL_image would decode).
bool read_image_header(std::span<const uint8_t> bytes, ImageHeader& out, std::string& why);

}  // namespace ds::render
