// The picture a frame is drawn into: an off-screen 32-bit surface of the
// game's own size. The window shows it scaled up, a capture writes it as it
// is, so what a test reads back is what a player sees.
#pragma once
#include <SDL.h>

#include <string>
#include <string_view>

#include "color.hpp"

namespace ds::render {

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

    Rgba pixel(int x, int y) const;  // (0, 0, 0, 0) outside
    // Writes the canvas as a PNG; throws RenderError naming the path.
    void save_png(const std::string& path) const;

private:
    void blend(int x, int y, Rgba c);  // no clipping: callers clip
    SDL_Surface* surface_ = nullptr;
};

// The largest canvas side accepted: beyond any display, and small enough
// that width × height × 4 bytes cannot overflow an int.
constexpr int kMaxCanvasSide = 16384;

}  // namespace ds::render
