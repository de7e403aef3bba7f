// SPDX-License-Identifier: MIT
#include "window.hpp"

#include <algorithm>

#include "constants.hpp"
#include "render_error.hpp"

namespace ds::render {

int fitting_scale(int width, int height, int bounds_w, int bounds_h) {
    if (width <= 0 || height <= 0) return 1;
    return std::clamp(std::min(bounds_w / width, bounds_h / height), 1, kMaxScale);
}

PictureView picture_view(int width, int height, int window_w, int window_h) {
    const int s = fitting_scale(width, height, window_w, window_h);
    return {(window_w - width * s) / 2, (window_h - height * s) / 2, s, width, height};
}

Window::Window(const std::string& title, int width, int height, int scale, bool fullscreen)
    : width_(width), height_(height) {
    if (SDL_InitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER) != 0)
        throw RenderError(std::string("cannot open a window: ") + SDL_GetError());
    if (scale <= 0) {
        SDL_Rect usable{0, 0, width, height};
        if (SDL_GetDisplayUsableBounds(0, &usable) != 0) usable = {0, 0, width, height};
        scale = fitting_scale(width, height, usable.w, usable.h);
    }
    scale_ = std::clamp(scale, 1, kMaxScale);
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               width * scale_, height * scale_, SDL_WINDOW_SHOWN | SDL_WINDOW_RESIZABLE);
    if (!window_) {
        const std::string why = SDL_GetError();
        SDL_QuitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER);
        throw RenderError("cannot open a window: " + why);
    }
    // Smaller than one picture pixel per pixel the picture would be cut.
    SDL_SetWindowMinimumSize(window_, width, height);
    if (fullscreen) set_fullscreen(true);
    open_vsync_renderer();
}

void Window::open_vsync_renderer() {
    // Only a renderer that really syncs is worth it: a software one (what
    // SDL offers under Xvfb) copies as the surface path does, more slowly.
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "nearest");
    renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC);
    SDL_RendererInfo info{};
    if (renderer_ && SDL_GetRendererInfo(renderer_, &info) == 0 && (info.flags & SDL_RENDERER_PRESENTVSYNC) &&
        !(info.flags & SDL_RENDERER_SOFTWARE))
        texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING, width_, height_);
    if (texture_) {
        vsync_ = true;
        return;
    }
    if (renderer_) SDL_DestroyRenderer(renderer_);
    renderer_ = nullptr;
}

Window::~Window() {
    if (texture_) SDL_DestroyTexture(texture_);
    if (renderer_) SDL_DestroyRenderer(renderer_);
    SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER);
}

PictureView Window::view() const {
    int w = 0, h = 0;
    SDL_GetWindowSize(window_, &w, &h);
    return picture_view(width_, height_, w, h);
}

void Window::present(const Canvas& canvas) {
    if (renderer_) present_by_renderer(canvas);
    else present_by_surface(canvas);
}

void Window::present_by_renderer(const Canvas& canvas) {
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(renderer_, &w, &h);  // pixels: a high-DPI window has more than its size
    const PictureView v = picture_view(canvas.width(), canvas.height(), w, h);
    const SDL_Surface* s = canvas.surface();
    SDL_UpdateTexture(texture_, nullptr, s->pixels, s->pitch);
    SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
    SDL_RenderClear(renderer_);
    const SDL_Rect dst{v.x, v.y, canvas.width() * v.scale, canvas.height() * v.scale};
    SDL_RenderCopy(renderer_, texture_, nullptr, &dst);
    SDL_RenderPresent(renderer_);  // waits for the vertical blank
}

void Window::present_by_surface(const Canvas& canvas) {
    SDL_Surface* screen = SDL_GetWindowSurface(window_);  // a new one after a resize
    if (!screen) throw RenderError(std::string("the window has no surface: ") + SDL_GetError());
    const PictureView v = picture_view(canvas.width(), canvas.height(), screen->w, screen->h);
    SDL_Rect dst{v.x, v.y, canvas.width() * v.scale, canvas.height() * v.scale};
    // The bars: black, and only where the picture is not (it covers the rest).
    if (v.x > 0 || v.y > 0 || dst.w < screen->w || dst.h < screen->h)
        SDL_FillRect(screen, nullptr, SDL_MapRGB(screen->format, 0, 0, 0));
    // The canvas never blends onto the screen, and a scaled blit copies the
    // nearest source pixel: every canvas pixel becomes a scale × scale block.
    if (v.scale == 1) SDL_BlitSurface(canvas.surface(), nullptr, screen, &dst);
    else SDL_BlitScaled(canvas.surface(), nullptr, screen, &dst);
    SDL_UpdateWindowSurface(window_);
}

void Window::poll(InputState& input) {
    input.set_view(view());
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
        if (e.type == SDL_KEYDOWN && !e.key.repeat &&
            (e.key.keysym.sym == SDLK_F11 || (e.key.keysym.sym == SDLK_RETURN && (e.key.keysym.mod & KMOD_ALT)))) {
            set_fullscreen(!fullscreen());
            continue;
        }
        if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) input.set_view(view());
        input.handle(e);
    }
}

void Window::set_fullscreen(bool on) {
    if (on == fullscreen_) return;
    if (on) {
        SDL_GetWindowPosition(window_, &windowed_.x, &windowed_.y);
        SDL_GetWindowSize(window_, &windowed_.w, &windowed_.h);
        SDL_Rect display{0, 0, windowed_.w, windowed_.h};
        const int index = SDL_GetWindowDisplayIndex(window_);
        if (SDL_GetDisplayBounds(index < 0 ? 0 : index, &display) != 0) return;  // nowhere to go: stay windowed
        SDL_SetWindowBordered(window_, SDL_FALSE);
        SDL_SetWindowResizable(window_, SDL_FALSE);
        SDL_SetWindowPosition(window_, display.x, display.y);
        SDL_SetWindowSize(window_, display.w, display.h);
        SDL_RaiseWindow(window_);
    } else {
        SDL_SetWindowBordered(window_, SDL_TRUE);
        SDL_SetWindowResizable(window_, SDL_TRUE);
        SDL_SetWindowSize(window_, windowed_.w, windowed_.h);
        SDL_SetWindowPosition(window_, windowed_.x, windowed_.y);
    }
    fullscreen_ = on;
}

bool Window::fullscreen() const { return fullscreen_; }

int Window::refresh_hz() const {
    SDL_DisplayMode mode{};
    const int index = SDL_GetWindowDisplayIndex(window_);
    if (SDL_GetCurrentDisplayMode(index < 0 ? 0 : index, &mode) != 0 || mode.refresh_rate <= 0) return kDefaultRefreshHz;
    return mode.refresh_rate;
}

}  // namespace ds::render
