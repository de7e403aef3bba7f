// SPDX-License-Identifier: MIT
// Displays as Scheme sees them: making one, its window (opening, closing,
// fullscreen, what the screen it is on can do), its clear colour, and
// reading back what it drew (stats, a pixel, a PNG written or compared).
#include <string>

#include "arguments.hpp"
#include "convert.hpp"
#include "display.hpp"
#include "failure.hpp"
#include "registry.hpp"

#include "frame_compare.hpp"
#include "render/constants.hpp"

namespace ds::guile {

namespace {

using namespace ds::render;

SCM make_display(SCM width, SCM height) {
    Failure f{"make-display"};
    int w = 0, h = 0;
    Display* d = nullptr;
    if (from_scm(width, w, "width", f, 1, kMaxCanvasSide) && from_scm(height, h, "height", f, 1, kMaxCanvasSide) &&
        int64_t(w) * h > kMaxCanvasPixels)
        fail(f, "wrong-type-arg", scm_list_3(width, height, scm_from_int64(kMaxCanvasPixels)),
             "width × height: ~S × ~S is more than ~S pixels (256 MiB a frame)");
    if (!f)
        guarded(f, nullptr, [&] {
            d = new Display;
            d->width = w;
            d->height = h;
        });
    if (f) raise(f);
    return wrap_display(d);
}

SCM open_window(SCM display, SCM title, SCM scale) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    std::string t;
    int s = 0;
    if (d)
        guarded(f, nullptr, [&] {
            if (!from_scm(title, t, "title", f) || !from_scm(scale, s, "scale", f, 0, 64)) return;
            d->window = std::make_unique<Window>(t, d->width, d->height, s, d->fullscreen);
            s = d->window->scale();
        });
    if (f) raise(f);
    return scm_from_int(s);
}

// Fullscreen on or off: now in an open window, and for a window opened later.
// Returns whether the window (or the wish, without one) is fullscreen.
SCM set_fullscreen(SCM display, SCM on) {
    Failure f;
    Display* d = display_of(display, "game-fullscreen-set!", f);
    bool now = false;
    if (d)
        guarded(f, nullptr, [&] {
            d->fullscreen = scm_is_true(on);
            if (d->window) d->window->set_fullscreen(d->fullscreen);
            now = d->window ? d->window->fullscreen() : d->fullscreen;
        });
    if (f) raise(f);
    return scm_from_bool(now);
}

SCM fullscreen_p(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-fullscreen?", f);
    if (f) raise(f);
    return scm_from_bool(d->window ? d->window->fullscreen() : d->fullscreen);
}

SCM refresh_rate(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    if (f) raise(f);
    return scm_from_int(d->window ? d->window->refresh_hz() : kDefaultRefreshHz);
}

SCM vsync_p(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    if (f) raise(f);
    return scm_from_bool(d->window && d->window->vsync());
}

SCM close_window(SCM display) {
    Failure f;
    if (Display* d = display_of(display, "game-run!", f)) guarded(f, nullptr, [&] { d->window.reset(); });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM display_stats(SCM display) {
    Failure f;
    Display* d = display_of(display, "engine-stats", f);
    if (f) raise(f);
    const DrawCounts& c = d->counts;
    return scm_list_4(scm_from_utf8_symbol("render"), scm_from_size_t(c.tiles + c.sprites + c.boxes + c.commands),
                      scm_from_size_t(d->culled), scm_from_double(d->ms));
}

SCM display_save_png(SCM display, SCM path) {
    Failure f;
    Display* d = display_of(display, "game-capture", f);
    std::string p;
    if (d)
        guarded(f, nullptr, [&] {
            if (from_scm(path, p, "file", f)) canvas_of(*d).save_png(p);
        });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM rgba_list(Rgba c) {
    return scm_list_4(scm_from_uint8(c.r), scm_from_uint8(c.g), scm_from_uint8(c.b), scm_from_uint8(c.a));
}

// The last frame drawn against a golden PNG: #f when they are the same;
// (size W H) when the golden picture is another size; else (count x y
// expected actual) for the pixels that differ, the first of them named.
// Either way that differs, writes the frame and a diff picture.
SCM display_compare_png(SCM display, SCM golden, SCM actual, SCM diff) {
    Failure f;
    Display* d = display_of(display, "check-frame", f);
    std::string g, a, df;
    FrameDiff r;
    if (d && from_scm(golden, g, "golden", f) && from_scm(actual, a, "actual", f) && from_scm(diff, df, "diff", f))
        guarded(f, nullptr, [&] { r = compare_with_png(canvas_of(*d), g, a, df); });
    if (f) raise(f);
    if (!r.same_size)
        return scm_list_3(scm_from_utf8_symbol("size"), scm_from_int(r.golden_width), scm_from_int(r.golden_height));
    if (r.differing == 0) return SCM_BOOL_F;
    return scm_list_5(scm_from_int64(r.differing), scm_from_int(r.first_x), scm_from_int(r.first_y),
                      rgba_list(r.expected), rgba_list(r.actual));
}

SCM display_pixel(SCM display, SCM x, SCM y) {
    Failure f;
    Display* d = display_of(display, "game-pixel", f);
    int px = 0, py = 0;
    Rgba c;
    if (d && from_scm(x, px, "x", f, 0, d->width - 1) && from_scm(y, py, "y", f, 0, d->height - 1))
        guarded(f, nullptr, [&] { c = canvas_of(*d).pixel(px, py); });
    if (f) raise(f);
    return scm_list_4(scm_from_uint8(c.r), scm_from_uint8(c.g), scm_from_uint8(c.b), scm_from_uint8(c.a));
}

SCM set_background(SCM display, SCM color) {
    Failure f;
    Display* d = display_of(display, "make-game", f);
    Rgba c;
    if (d && scm_is_false(color)) {
        d->background.reset();
    } else if (d) {
        Failure quiet;  // color_arg names the argument "color": make-game's is background
        if (color_arg(color, c, quiet)) d->background = Rgba{c.r, c.g, c.b, 255};  // a clear colour is opaque
        else fail_arg(f, "background", color, "(r g b) or (r g b a) of integers 0–255, or #f");
    }
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM renderer_p() { return SCM_BOOL_T; }

}  // namespace

void register_display_procedures() {
#define DS_NATIVE DS_DEFINE_NATIVE
#define DS_RENDER_NATIVE DS_DEFINE_NATIVE
#include "display.def"
#undef DS_NATIVE
#undef DS_RENDER_NATIVE
}

}  // namespace ds::guile
