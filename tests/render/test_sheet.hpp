// SPDX-License-Identifier: MIT
// The test tile sheet the renderer's suites draw from: a 2 × 2 sheet of
// 4 × 4 px tiles whose every pixel differs, written as a PNG, and a map of
// them, so a misplaced, flipped or shifted pixel shows.
#pragma once
#include <SDL_image.h>
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "canvas.hpp"
#include "tilemap/tilemap.hpp"

namespace ds::render::test {

constexpr int kTile = 4;   // test tiles are 4 × 4 px
constexpr int kSheetCols = 2;

// The test sheet's colour at pixel (u, v) of local tile t: every pixel of
// every tile differs, so any misplaced, flipped or shifted pixel shows.
inline Rgba sheet_color(int t, int u, int v) {
    return {uint8_t(40 + 50 * t), uint8_t(20 + 60 * u), uint8_t(10 + 70 * v), 255};
}

inline std::filesystem::path temp_dir() {
    auto dir = std::filesystem::temp_directory_path() / ("ds-render-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

// Writes a 2 × 2 sheet of 4 × 4 tiles (ids 0–3) as a PNG, opaque.
inline std::string write_sheet(const std::string& name) {
    SDL_Surface* s = SDL_CreateRGBSurfaceWithFormat(0, kTile * kSheetCols, kTile * 2, 32, SDL_PIXELFORMAT_ARGB8888);
    for (int t = 0; t < 4; ++t)
        for (int v = 0; v < kTile; ++v)
            for (int u = 0; u < kTile; ++u) {
                const Rgba c = sheet_color(t, u, v);
                const int x = (t % kSheetCols) * kTile + u, y = (t / kSheetCols) * kTile + v;
                static_cast<uint32_t*>(s->pixels)[y * s->pitch / 4 + x] =
                    0xff000000u | uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b;
            }
    const auto path = temp_dir() / name;
    REQUIRE(IMG_SavePNG(s, path.string().c_str()) == 0);
    SDL_FreeSurface(s);
    return path.string();
}

inline Tileset sheet_tileset() {
    write_sheet("sheet.png");
    Tileset ts;
    ts.firstgid = 1;
    ts.name = "sheet";
    ts.tile_width = ts.tile_height = kTile;
    ts.tile_count = 4;
    ts.columns = kSheetCols;
    ts.image = "sheet.png";
    ts.image_dir = temp_dir().string();
    return ts;
}

// A cols × rows map of 4 px cells whose one layer holds `cells`.
inline Tilemap map_with(int cols, int rows, std::vector<uint32_t> cells) {
    Tilemap m;
    m.width = cols;
    m.height = rows;
    m.tile_width = m.tile_height = kTile;
    m.tilesets.push_back(sheet_tileset());
    TileLayer layer;
    layer.width = cols;
    layer.height = rows;
    layer.cells = std::move(cells);
    m.layers.push_back(std::move(layer));
    return m;
}

}  // namespace ds::render::test
