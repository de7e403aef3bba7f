// SPDX-License-Identifier: MIT
#include "image_header.hpp"

#include <cstring>

namespace ds::render {

namespace {

uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }
uint32_t be16(const uint8_t* p) { return uint32_t(p[0]) << 8 | p[1]; }
uint32_t le16(const uint8_t* p) { return uint32_t(p[1]) << 8 | p[0]; }
uint32_t le32(const uint8_t* p) { return uint32_t(p[3]) << 24 | uint32_t(p[2]) << 16 | uint32_t(p[1]) << 8 | p[0]; }

bool starts(std::span<const uint8_t> b, const char* magic, size_t n) {
    return b.size() >= n && std::memcmp(b.data(), magic, n) == 0;
}

bool sized(ImageHeader& out, const char* format, int64_t w, int64_t h, std::string& why) {
    out.format = format;
    out.width = w, out.height = h;
    if (w > 0 && h > 0) return true;
    why = std::string("its ") + format + " header declares a size of " + std::to_string(w) + "x" +
          std::to_string(h) + " px";
    return false;
}

// PNG: the 8-byte signature, then the IHDR chunk: length 13, "IHDR", width
// and height big-endian (each at most 2^31 − 1 by the format).
bool png(std::span<const uint8_t> b, ImageHeader& out, std::string& why) {
    if (b.size() < 24 || std::memcmp(b.data() + 12, "IHDR", 4) != 0) {
        why = "its PNG header is cut short or has no IHDR chunk first";
        return false;
    }
    const uint32_t w = be32(b.data() + 16), h = be32(b.data() + 20);
    if (w > 0x7fffffffu || h > 0x7fffffffu) {
        why = "its PNG header declares a size beyond the format's (" + std::to_string(w) + "x" + std::to_string(h) + ")";
        return false;
    }
    return sized(out, "PNG", w, h, why);
}

// GIF: "GIF87a"/"GIF89a", the logical screen (width, height, flags: a
// global colour table of 3 × 2^(n+1) bytes follows when the top bit is
// set), then blocks: extensions ('!', a label, sub-blocks of a length byte
// and that many bytes, up to an empty one), image descriptors (',', left,
// top, width, height, flags: a local colour table likewise, then the LZW
// code size) and the trailer (';'). SDL_image 2.6 decodes the first image
// it can allocate, at that image's size, whatever the screen's (a 35-byte
// GIF with a 4x4 screen and a 65535x65535 image reached 4.1 GB): it skips
// any other byte between blocks, and an image whose code size is above 12
// or whose width or height is 0, going on from the byte after the code
// size. This walk does the same, so its size is the one SDL_image allocates.
// A code size of 0 or 1, which no encoder writes, is refused: SDL_image's
// LZW decoder then writes past its tables (found by fuzz_decode.cpp).
bool gif(std::span<const uint8_t> b, ImageHeader& out, std::string& why) {
    if (b.size() < 13) {
        why = "its GIF header is cut short";
        return false;
    }
    const auto colour_table = [](uint8_t flags) { return flags & 0x80 ? 3 * (size_t(2) << (flags & 7)) : 0; };
    size_t i = 13 + colour_table(b[10]);
    while (i < b.size()) {
        const uint8_t c = b[i++];
        if (c == ';') break;
        if (c == '!') {
            ++i;  // the label
            while (i < b.size() && b[i] != 0) i += 1 + size_t(b[i]);
            ++i;  // the empty sub-block
        } else if (c == ',') {
            if (i + 9 > b.size()) break;
            const uint32_t w = le16(b.data() + i + 4), h = le16(b.data() + i + 6);
            i += 9 + colour_table(b[i + 8]);
            if (i >= b.size()) break;
            const uint8_t code_size = b[i++];
            if (code_size > 12 || w == 0 || h == 0) continue;
            if (code_size < 2) {  // the GIF format's least is 2, for 1-bit pictures
                why = "its GIF image has an LZW code size of " + std::to_string(code_size) +
                      " (at least 2: SDL_image 2.6 corrupts its heap decoding less)";
                return false;
            }
            return sized(out, "GIF", w, h, why);
        }
    }
    why = "its GIF data has no image (or is cut short before it)";
    return false;
}

// BMP: "BM", a 14-byte file header, then the DIB header: BITMAPCOREHEADER
// (12 bytes, 16-bit sizes) or any larger one (signed 32-bit width and
// height; a negative height is a top-down picture of that many rows).
bool bmp(std::span<const uint8_t> b, ImageHeader& out, std::string& why) {
    if (b.size() < 26) {
        why = "its BMP header is cut short";
        return false;
    }
    const uint32_t dib = le32(b.data() + 14);
    if (dib == 12) return sized(out, "BMP", le16(b.data() + 18), le16(b.data() + 20), why);
    if (dib < 40 || b.size() < 26) {
        why = "its BMP header is of an unknown kind (" + std::to_string(dib) + " bytes)";
        return false;
    }
    const auto w = int32_t(le32(b.data() + 18)), h = int32_t(le32(b.data() + 22));
    return sized(out, "BMP", w, h == INT32_MIN ? 0 : (h < 0 ? -int64_t(h) : h), why);
}

// JPEG: SOI, then segments (0xFF, marker, big-endian length including
// itself) up to a start-of-frame (SOF0–SOF15 but DHT C4, JPG C8, DAC CC),
// whose height and width follow its precision byte.
bool jpeg(std::span<const uint8_t> b, ImageHeader& out, std::string& why) {
    size_t i = 2;
    while (i + 4 <= b.size()) {
        if (b[i] != 0xFF) {
            why = "its JPEG segments are corrupt at byte " + std::to_string(i);
            return false;
        }
        const uint8_t marker = b[i + 1];
        if (marker == 0xFF) {  // fill bytes
            ++i;
            continue;
        }
        if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length
            i += 2;
            continue;
        }
        const uint32_t len = be16(b.data() + i + 2);
        if (len < 2) {
            why = "its JPEG segments are corrupt at byte " + std::to_string(i);
            return false;
        }
        const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (sof) {
            if (i + 9 > b.size()) break;
            return sized(out, "JPEG", be16(b.data() + i + 7), be16(b.data() + i + 5), why);
        }
        if (marker == 0xD9 || marker == 0xDA) {  // end of image, or scan data before any frame
            why = "its JPEG data has no frame header before its image data";
            return false;
        }
        i += 2 + size_t(len);
    }
    why = "its JPEG header is cut short before the frame's size";
    return false;
}

}  // namespace

bool read_image_header(std::span<const uint8_t> b, ImageHeader& out, std::string& why) {
    if (starts(b, "\x89PNG\r\n\x1a\n", 8)) return png(b, out, why);
    if (starts(b, "\xFF\xD8\xFF", 3)) return jpeg(b, out, why);
    if (starts(b, "GIF87a", 6) || starts(b, "GIF89a", 6)) return gif(b, out, why);
    if (starts(b, "BM", 2)) return bmp(b, out, why);
    why = b.empty() ? "it is empty" : "it is not a PNG, JPEG, GIF or BMP image";
    return false;
}

}  // namespace ds::render
