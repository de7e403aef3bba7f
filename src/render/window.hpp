// A real window that shows a canvas scaled up by a whole factor (nearest
// pixel, no blur), and the source of keyboard, controller and close events.
#pragma once
#include <SDL.h>

#include <string>

#include "canvas.hpp"
#include "input.hpp"

namespace ds::render {

class Window {
public:
    // Opens a window for a width × height canvas at `scale` (0: the largest
    // whole factor, up to kMaxScale, that fits the display's usable area).
    // Throws RenderError with SDL's reason (no display, no video driver).
    Window(const std::string& title, int width, int height, int scale);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    int scale() const { return scale_; }
    // Shows the canvas, scaled. Throws RenderError when the window's surface is gone.
    void present(const Canvas& canvas);
    // Feeds every pending event to `input`.
    void poll(InputState& input);

private:
    SDL_Window* window_ = nullptr;
    int scale_ = 1;
};

// The largest whole scale at which width × height fits in bounds_w × bounds_h
// (at least 1, at most kMaxScale).
int fitting_scale(int width, int height, int bounds_w, int bounds_h);

}  // namespace ds::render
