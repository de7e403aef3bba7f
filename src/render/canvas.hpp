// SPDX-License-Identifier: MIT
// The picture a frame is drawn into: an off-screen 32-bit surface of the
// game's own size. The window shows it scaled up, a capture writes it as it
// is, so what a test reads back is what a player sees.
#pragma once
#include <SDL.h>

#include <cstdint>

#include <string>
#include <string_view>

#include "color.hpp"

namespace ds::render {

// Where Canvas::draw_picture puts a picture, in canvas px.
struct PictureBox {
    double cx = 0, cy = 0, w = 0, h = 0;
    double degrees = 0, pivot_x = 0, pivot_y = 0;
    // The picture runs against its source image along x (y): a tile's
    // horizontal (vertical) flip. Where sampling ties, the source pixel
    // before the tie is taken, so a flipped axis takes the one after it.
    bool reversed_x = false, reversed_y = false;
    // The picture is its source image transposed (a tile's diagonal flip).
    bool transposed = false;
};

class Canvas {
public:
    // Throws RenderError for a size that is not positive or too large.
    Canvas(int width, int height);
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    int width() const { return surface_->w; }
    int height() const { return surface_->h; }
    SDL_Surface* surface() const { return surface_; }

    void clear(Rgba c);
    // Pixels blend over what is there by the colour's alpha; everything is
    // clipped to the canvas, so any coordinates are safe.
    void fill_rect(int x, int y, int w, int h, Rgba c);
    void outline_rect(int x, int y, int w, int h, Rgba c);
    void line(int x0, int y0, int x1, int y1, Rgba c);
    // Built-in font; "\n" starts a new line under the first.
    void text(int x, int y, std::string_view s, Rgba c, int scale = 1);
    // A picture at (x, y), blended as its own blend mode says, faded by alpha.
    void blit(SDL_Surface* picture, int x, int y, uint8_t alpha = 255);

    // A picture stretched over the box centred on (cx, cy), w × h px, turned
    // `degrees` clockwise about (pivot_x, pivot_y): each canvas pixel whose
    // centre falls in the box takes the nearest picture pixel (no smoothing,
    // as Tiled's --no-smoothing), multiplied by `tint` (all four channels,
    // c·t/255) and faded by alpha. Any coordinates are safe.
    void draw_picture(SDL_Surface* picture, const PictureBox& box, uint8_t alpha = 255, Rgba tint = {255, 255, 255, 255});

    Rgba pixel(int x, int y) const;  // (0, 0, 0, 0) outside
    // Writes the canvas as a PNG to a regular file (new or replaced; a
    // FIFO, a device or a folder is refused, never waited on), every write
    // checked, beside it first and renamed over it once whole; throws
    // RenderError naming the path, leaving the file that was there as it was.
    void save_png(const std::string& path) const;

private:
    void blend(int x, int y, Rgba c);  // no clipping: callers clip
    SDL_Surface* surface_ = nullptr;
};

// The largest canvas side accepted: beyond any display, and small enough
// that width × height × 4 bytes cannot overflow an int.
constexpr int kMaxCanvasSide = 16384;
// The most pixels a canvas holds: 2^26 (256 MiB at 4 bytes a pixel, 8192 ×
// 8192 or 16384 × 4096), so the largest game a script may make is drawn and
// captured within a bounded allocation, not 1 GiB for 16384 × 16384.
constexpr int64_t kMaxCanvasPixels = int64_t(1) << 26;

}  // namespace ds::render
