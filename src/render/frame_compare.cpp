// SPDX-License-Identifier: MIT
#include "frame_compare.hpp"

#include <SDL.h>

#include "tile_art.hpp"

namespace ds::render {

namespace {

// The colour drawn for a pixel that differs: magenta, which no frame is
// likely to hold in bulk and every artist reads as "look here".
constexpr Rgba kDiffColor{255, 0, 255, 255};

Rgba argb_at(const SDL_Surface* s, int x, int y) {
    const uint32_t v = static_cast<const uint32_t*>(s->pixels)[y * (s->pitch / 4) + x];
    return {uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v), uint8_t(v >> 24)};
}

}  // namespace

FrameDiff compare_with_png(const Canvas& canvas, const std::string& golden, const std::string& actual_png,
                           const std::string& diff_png) {
    TileArt art;  // reads and converts the picture, bounds checked; frees it after
    const SDL_Surface* g = art.picture(golden, std::nullopt, 0, 0, "the golden picture");
    FrameDiff d;
    d.golden_width = g->w;
    d.golden_height = g->h;
    d.same_size = g->w == canvas.width() && g->h == canvas.height();
    if (d.same_size)
        for (int y = 0; y < g->h; ++y)
            for (int x = 0; x < g->w; ++x) {
                const Rgba want = argb_at(g, x, y), got = canvas.pixel(x, y);
                if (want == got) continue;
                if (d.differing++ == 0) d.first_x = x, d.first_y = y, d.expected = want, d.actual = got;
            }
    if (d.same_size && d.differing == 0) return d;
    canvas.save_png(actual_png);
    Canvas diff(canvas.width(), canvas.height());
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) {
            const Rgba got = canvas.pixel(x, y);
            const bool differs = !d.same_size || x >= g->w || y >= g->h || argb_at(g, x, y) != got;
            diff.fill_rect(x, y, 1, 1, differs ? kDiffColor : Rgba{uint8_t(got.r / 3), uint8_t(got.g / 3), uint8_t(got.b / 3), 255});
        }
    diff.save_png(diff_png);
    return d;
}

}  // namespace ds::render
