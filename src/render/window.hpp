// SPDX-License-Identifier: MIT
// A real window that shows a canvas scaled up by a whole factor (nearest
// pixel, no blur), centred with black bars when the window is larger, and
// the source of keyboard, mouse, controller and close events. It can be
// resized, and made fullscreen and back (F11 or Alt+Return, or the game).
#pragma once
#include <SDL.h>

#include <string>

#include "canvas.hpp"
#include "input.hpp"

namespace ds::render {

class Window {
public:
    // Opens a resizable window for a width × height canvas at `scale` (0:
    // the largest whole factor, up to kMaxScale, that fits the display's
    // usable area), or fullscreen on the desktop's resolution.
    // Throws RenderError with SDL's reason (no display, no video driver).
    Window(const std::string& title, int width, int height, int scale, bool fullscreen = false);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // The scale the window opened at (what --scale chose).
    int scale() const { return scale_; }
    // Where the picture is in the window as it is now: the largest whole
    // scale at which it fits (at least 1), centred.
    PictureView view() const;
    // Shows the canvas scaled and centred, the rest black: through an SDL
    // renderer on vsync when the system gives one, else by the window's
    // surface. Throws RenderError when the window's surface is gone.
    void present(const Canvas& canvas);
    // Whether presenting waits for the display's vertical blank.
    bool vsync() const { return vsync_; }
    // Feeds every pending event to `input`; F11 and Alt+Return toggle
    // fullscreen here and reach no binding.
    void poll(InputState& input);

    void set_fullscreen(bool on);
    bool fullscreen() const;
    // The refresh rate of the display the window is on, in Hz; 60 when
    // SDL does not know it (Xvfb, some drivers).
    int refresh_hz() const;

private:
    SDL_Window* window_ = nullptr;
    int width_ = 0, height_ = 0;  // the picture's, in its own pixels
    int scale_ = 1;
    // Fullscreen is a borderless window over the whole display (what games
    // call "borderless fullscreen"): it needs no mode switch and no window
    // manager's help, so it behaves the same under every X server, Xvfb
    // included. `windowed_` is where to go back to.
    bool fullscreen_ = false;
    SDL_Rect windowed_{0, 0, 0, 0};
    // The vsync path: a renderer that presents on the vertical blank and a
    // streaming texture the canvas is copied into each frame. Null when the
    // system has none (Xvfb, a bare framebuffer): the surface path is used.
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* texture_ = nullptr;
    bool vsync_ = false;
    void open_vsync_renderer();
    void present_by_renderer(const Canvas& canvas);
    void present_by_surface(const Canvas& canvas);
};

// The largest whole scale at which width × height fits in bounds_w × bounds_h
// (at least 1, at most kMaxScale).
int fitting_scale(int width, int height, int bounds_w, int bounds_h);

// Where a width × height picture goes in a window_w × window_h window:
// fitting_scale, centred (an odd leftover puts the extra pixel right and
// below).
PictureView picture_view(int width, int height, int window_w, int window_h);

}  // namespace ds::render
