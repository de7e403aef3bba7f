// SPDX-License-Identifier: MIT
// Images a map names, however hostile (issue 35): each file's header is read
// before anything is decoded, a declared size past the bounds is refused
// naming the file and the size, and nothing is allocated for it; truncated,
// corrupt and non-image files and directories are refused naming the file;
// an image whose real size is not the declared one is drawn at its real
// size with a warning naming both.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>

#include "child_process.hpp"
#include "constants.hpp"
#include "image_header.hpp"
#include "render_error.hpp"
#include "scene_draw.hpp"
#include "test_sheet.hpp"

using namespace ds;
using namespace ds::render;
using namespace ds::render::test;

namespace {

std::vector<uint8_t> bytes(std::initializer_list<int> v) {
    std::vector<uint8_t> out;
    for (int b : v) out.push_back(uint8_t(b));
    return out;
}

void be32(std::vector<uint8_t>& v, uint32_t x) {
    for (int s = 24; s >= 0; s -= 8) v.push_back(uint8_t(x >> s));
}

// A PNG signature and IHDR declaring w × h, then `tail` bytes of junk: what
// an image bomb's first bytes look like.
std::vector<uint8_t> png_head(uint32_t w, uint32_t h, size_t tail = 0) {
    std::vector<uint8_t> v = bytes({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'});
    be32(v, w);
    be32(v, h);
    v.insert(v.end(), {8, 6, 0, 0, 0});
    v.resize(v.size() + tail, 0x55);
    return v;
}

std::string write_file(const std::string& name, const std::vector<uint8_t>& data) {
    const std::string path = (temp_dir() / name).string();
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
    return path;
}

// A one-cell map whose tileset's image is `image` (in the test's folder),
// declared image_w × image_h.
Tilemap map_on(const std::string& image, int image_w = 8, int image_h = 8) {
    Tilemap m = map_with(1, 1, {1});
    m.tilesets[0].image = image;
    m.tilesets[0].image_width = image_w, m.tilesets[0].image_height = image_h;
    return m;
}

std::string draw_error(const Tilemap& m) {
    Canvas c(4, 4);
    TileArt art;
    art.bind(&m);
    try {
        draw_map(c, art, m, 0, 0);
    } catch (const RenderError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_SUITE("image-limits") {

TEST_CASE("read_image_header reads each format's declared size") {
    ImageHeader h;
    std::string why;
    REQUIRE(read_image_header(png_head(30000, 20000), h, why));
    CHECK(std::string(h.format) == "PNG");
    CHECK(h.width == 30000);
    CHECK(h.height == 20000);
    // GIF: SDL_image decodes the first image at its descriptor's size, not
    // the logical screen's (0x1234 x 0x0102 here); a comment extension and
    // a stray byte come before it.
    REQUIRE(read_image_header(bytes({'G', 'I', 'F', '8', '9', 'a', 0x34, 0x12, 0x02, 0x01, 0, 0, 0, '!', 0xFE, 2, 'h',
                                     'i', 0, 0x07, ',', 0, 0, 0, 0, 0x04, 0x03, 0x06, 0x05, 0, 2}),
                              h, why));
    CHECK(h.width == 0x0304);
    CHECK(h.height == 0x0506);
    // Images SDL_image cannot allocate (an LZW code size above 12, a width
    // of 0) are passed over, as it passes them, for the next.
    REQUIRE(read_image_header(bytes({'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0, ',', 0, 0, 0, 0, 9, 0, 9, 0, 0,
                                     13, ',', 0, 0, 0, 0, 0, 0, 9, 0, 0, 2, ',', 0, 0, 0, 0, 7, 0, 8, 0, 0, 2}),
                              h, why));
    CHECK(h.width == 7);
    CHECK(h.height == 8);
    // A code size below 2 crashes SDL_image 2.6's decoder: refused.
    CHECK_FALSE(read_image_header(bytes({'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0, ',', 0, 0, 0, 0, 9, 0, 9,
                                         0, 0, 1}),
                                  h, why));
    CHECK(why == "its GIF image has an LZW code size of 1 (at least 2: SDL_image 2.6 corrupts its heap decoding less)");
    // BMP with a 40-byte header and a negative (top-down) height.
    std::vector<uint8_t> bmp = bytes({'B', 'M', 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 40, 0, 0, 0, 0x20, 0, 0, 0,
                                      0xF0, 0xFF, 0xFF, 0xFF});
    REQUIRE(read_image_header(bmp, h, why));
    CHECK(h.width == 32);
    CHECK(h.height == 16);
    // JPEG: SOI, an APP0 segment of 16 bytes, then SOF0 (precision 8, height 300, width 400).
    std::vector<uint8_t> jpg = bytes({0xFF, 0xD8, 0xFF, 0xE0, 0, 16});
    jpg.resize(jpg.size() + 14, 0);
    for (int b : {0xFF, 0xC0, 0, 17, 8, 0x01, 0x2C, 0x01, 0x90}) jpg.push_back(uint8_t(b));
    REQUIRE(read_image_header(jpg, h, why));
    CHECK(std::string(h.format) == "JPEG");
    CHECK(h.width == 400);
    CHECK(h.height == 300);
}

TEST_CASE("read_image_header says what is wrong with anything else") {
    ImageHeader h;
    std::string why;
    CHECK_FALSE(read_image_header({}, h, why));
    CHECK(why == "it is empty");
    CHECK_FALSE(read_image_header(bytes({'h', 'e', 'l', 'l', 'o'}), h, why));
    CHECK(why == "it is not a PNG, JPEG, GIF or BMP image");
    std::vector<uint8_t> cut = png_head(16, 16);
    cut.resize(20);
    CHECK_FALSE(read_image_header(cut, h, why));
    CHECK(why == "its PNG header is cut short or has no IHDR chunk first");
    CHECK_FALSE(read_image_header(png_head(0, 16), h, why));
    CHECK(why == "its PNG header declares a size of 0x16 px");
    CHECK_FALSE(read_image_header(png_head(0x80000000u, 1), h, why));
    CHECK(why == "its PNG header declares a size beyond the format's (2147483648x1)");
    CHECK_FALSE(read_image_header(bytes({0xFF, 0xD8, 0xFF, 0xE0, 0, 40}), h, why));
    CHECK(why == "its JPEG header is cut short before the frame's size");
}

TEST_CASE("an image bomb is refused from its header, naming the file and the size, without decoding it") {
    const std::string bomb = write_file("bomb.png", png_head(30000, 30000, 4096));
    CHECK(draw_error(map_on("bomb.png", 32, 32)) ==
          "refusing tileset image '" + bomb + "': its PNG header declares 30000x30000 px, more than the limit of "
          "16384 px a side");
    const std::string big = write_file("big.png", png_head(16384, 16384, 4096));
    CHECK(draw_error(map_on("big.png", 32, 32)) ==
          "refusing tileset image '" + big + "': its PNG header declares 16384x16384 px, 1024 MiB decoded, more "
          "than the limit of 256 MiB");
    // In a child, drawing the bomb's map costs next to nothing: it is never decoded.
    const long kb = child_peak_kb([] {
        const Tilemap m = map_on("bomb.png", 32, 32);
        (void)draw_error(m);
    });
    CAPTURE(kb);
    CHECK(kb >= 0);
    CHECK(kb < 16 * 1024);  // well under one decoded row band of the bomb (30000 × 4 × 140 B)
}

// The audit's 35-byte GIF: a 4 x 4 logical screen, then an image descriptor
// of 65535 x 65535 px, which is what SDL_image sizes the picture by (4.1 GB
// before the header check read the descriptor).
std::vector<uint8_t> gif_bomb() {
    return bytes({'G', 'I', 'F', '8', '9', 'a', 4, 0, 4, 0, 0, 0, 0, ',', 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0, 2,
                  2, 0x4C, 0x01, 0, ';', 0, 0, 0, 0, 0, 0});
}

TEST_CASE("a GIF whose first image is a bomb behind a small screen is refused from that image's size") {
    const std::vector<uint8_t> bomb = gif_bomb();
    REQUIRE(bomb.size() == 35);
    const std::string path = write_file("bomb.gif", bomb);
    CHECK(draw_error(map_on("bomb.gif", 4, 4)) ==
          "refusing tileset image '" + path + "': its GIF header declares 65535x65535 px, more than the limit of "
          "16384 px a side");
    const long kb = child_peak_kb([] {
        const Tilemap m = map_on("bomb.gif", 4, 4);
        (void)draw_error(m);
    });
    CAPTURE(kb);
    CHECK(kb >= 0);
    CHECK(kb < 16 * 1024);
}

TEST_CASE("a GIF is refused naming the file: SDL_image's GIF decoder is not safe on hostile files") {
    // 1 x 1, a two-colour table, one pixel of LZW data: a valid GIF.
    const std::string path = write_file(
        "one.gif", bytes({'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0x80, 0, 0, 255, 255, 255, 0, 0, 0, ',', 0, 0, 0, 0,
                          1, 0, 1, 0, 0, 2, 2, 0x44, 0x01, 0, ';'}));
    CHECK(draw_error(map_on("one.gif", 1, 1)) ==
          "refusing tileset image '" + path +
              "': GIF is not loaded (SDL_image's GIF decoder is unsafe on hostile files); convert it to PNG");
}

TEST_CASE("an image file larger than an image can be, or not a regular file, is refused unread") {
    // Sparse: a PNG header, then a hole up to one byte past the bound.
    const std::string huge = write_file("huge.png", png_head(8, 8));
    REQUIRE(truncate(huge.c_str(), kMaxImageFileBytes + 1) == 0);
    CHECK(draw_error(map_on("huge.png")) == "cannot read tileset image '" + huge + "': is " +
                                                std::to_string(kMaxImageFileBytes + 1) + " bytes, more than the " +
                                                std::to_string(kMaxImageFileBytes) + " bytes an image file may hold");
    const std::string fifo = (temp_dir() / "pipe.png").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);  // opening it for reading would wait for a writer
    CHECK(draw_error(map_on("pipe.png")) == "cannot read tileset image '" + fifo + "': is not a regular file (a FIFO)");
    std::filesystem::remove(fifo);
}

TEST_CASE("truncated, corrupt and non-image files and folders are refused naming the file") {
    std::vector<uint8_t> truncated = png_head(8, 8);
    const std::string cut = write_file("cut.png", truncated);  // a header and no image data
    CHECK(draw_error(map_on("cut.png")).rfind("cannot read tileset image '" + cut + "': ", 0) == 0);
    const std::string text = write_file("text.png", bytes({'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'}));
    CHECK(draw_error(map_on("text.png")) ==
          "cannot read tileset image '" + text + "': it is not a PNG, JPEG, GIF or BMP image");
    const std::string empty = write_file("empty.png", {});
    CHECK(draw_error(map_on("empty.png")) == "cannot read tileset image '" + empty + "': it is empty");
    std::filesystem::create_directories(temp_dir() / "folder.png");
    CHECK(draw_error(map_on("folder.png")) ==
          "cannot read tileset image '" + (temp_dir() / "folder.png").string() + "': is a directory");
}

TEST_CASE("an image not of its declared size is drawn at its real size, with a warning naming both") {
    write_sheet("sheet.png");  // 8 × 8: 2 × 2 tiles of 4 px
    Tilemap m = map_on("sheet.png", 16, 8);  // declared 16 × 8: 4 columns, if it were so
    m.tilesets[0].columns = 4;
    m.layers[0].cells = std::vector<uint32_t>{3};  // tile 2: row 1, column 0 of the real 2-column image
    Canvas c(4, 4);
    TileArt art;
    art.bind(&m);
    draw_map(c, art, m, 0, 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) CHECK(c.pixel(x, y) == sheet_color(2, x, y));
    const std::vector<std::string> w = art.take_warnings();
    REQUIRE(w.size() == 1);
    CHECK(w[0] == "tileset image '" + (temp_dir() / "sheet.png").string() +
                      "' is 8x8 px, but the map declares 16x8; drawn at its real size, as Tiled does");
    draw_map(c, art, m, 0, 0);
    CHECK(art.take_warnings().empty());  // once per image
}

}  // TEST_SUITE
