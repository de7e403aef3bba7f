// SPDX-License-Identifier: MIT
// The display the renderer's procedures share: one per game, an off-screen
// canvas, the tile pictures, the render hook's draw list, and optionally a
// window with its input. Built only with SDL2 (render_missing.cpp stands in
// for every procedure without it).
#pragma once
#include <libguile.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contacts.hpp"
#include "failure.hpp"

#include "canvas.hpp"
#include "draw_list.hpp"
#include "input.hpp"
#include "interpolate.hpp"
#include "scene_draw.hpp"
#include "tile_animation.hpp"
#include "tile_art.hpp"
#include "window.hpp"

namespace ds::guile {

// Everything one game draws with. Plain C++: no SCM is kept here.
struct Display {
    int width = 0, height = 0;
    std::unique_ptr<render::Canvas> canvas;  // made when first drawn
    render::TileArt art;
    render::DrawList commands;
    std::unique_ptr<render::Window> window;
    bool fullscreen = false;  // asked for (--fullscreen, game-fullscreen-set!), also before a window opens
    render::InputState input;
    std::vector<std::string> actions;  // by action number
    // Per-frame scratch, kept so a frame does not allocate.
    std::vector<render::EntityView> entities;
    std::vector<render::EntityView> before;             // the step before, when drawing between two
    std::vector<int64_t> now_ids, before_ids;   // their #:id tags
    std::vector<render::Trail> trails;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    std::vector<AnimationFrame> frames;  // an #:animation list's, while it is read
    render::DrawCounts counts;
    size_t culled = 0;
    double ms = 0;
    std::optional<render::Rgba> background;  // make-game's background:, else the map's
    std::vector<std::string> warnings;  // drawing's, until written to the warning port
};

// The display a Scheme value holds, or nullptr with a failure naming `proc`
// (the public procedure) when it holds none.
Display* display_of(SCM obj, const char* proc, Failure& f);

// Its canvas, made when first drawn.
render::Canvas& canvas_of(Display& d);

// A Scheme value owning `d`, which the collector deletes with it.
SCM wrap_display(Display* d);

// The renderer's procedures, by concern: each file registers its own table
// (the .def file of the same name here).
void register_display_procedures();  // display_procs.cpp: displays, windows, capture
void register_draw_procedures();     // draw_procs.cpp: frames and draw commands
void register_input_procedures();    // input_procs.cpp: input maps and polling
void register_audio_procedures();    // audio_procs.cpp: sounds and music

}  // namespace ds::guile
