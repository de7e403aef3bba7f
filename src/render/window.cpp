#include "window.hpp"

#include <algorithm>

#include "constants.hpp"
#include "render_error.hpp"

namespace ds::render {

int fitting_scale(int width, int height, int bounds_w, int bounds_h) {
    if (width <= 0 || height <= 0) return 1;
    return std::clamp(std::min(bounds_w / width, bounds_h / height), 1, kMaxScale);
}

Window::Window(const std::string& title, int width, int height, int scale) {
    if (SDL_InitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER) != 0)
        throw RenderError(std::string("cannot open a window: ") + SDL_GetError());
    if (scale <= 0) {
        SDL_Rect usable{0, 0, width, height};
        if (SDL_GetDisplayUsableBounds(0, &usable) != 0) usable = {0, 0, width, height};
        scale = fitting_scale(width, height, usable.w, usable.h);
    }
    scale_ = std::clamp(scale, 1, kMaxScale);
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               width * scale_, height * scale_, SDL_WINDOW_SHOWN);
    if (!window_) {
        const std::string why = SDL_GetError();
        SDL_QuitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER);
        throw RenderError("cannot open a window: " + why);
    }
}

Window::~Window() {
    SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER);
}

void Window::present(const Canvas& canvas) {
    SDL_Surface* screen = SDL_GetWindowSurface(window_);
    if (!screen) throw RenderError(std::string("the window has no surface: ") + SDL_GetError());
    SDL_Rect dst{0, 0, canvas.width() * scale_, canvas.height() * scale_};
    // The canvas never blends onto the screen, and a scaled blit copies the
    // nearest source pixel: every canvas pixel becomes a scale × scale block.
    if (scale_ == 1) SDL_BlitSurface(canvas.surface(), nullptr, screen, &dst);
    else SDL_BlitScaled(canvas.surface(), nullptr, screen, &dst);
    SDL_UpdateWindowSurface(window_);
}

void Window::poll(InputState& input) {
    SDL_Event e;
    while (SDL_PollEvent(&e)) input.handle(e);
}

}  // namespace ds::render
