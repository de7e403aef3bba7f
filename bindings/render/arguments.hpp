// SPDX-License-Identifier: MIT
// The arguments the renderer's procedures share: colours, the space a draw
// command is in, gids and symbols.
#pragma once
#include <libguile.h>

#include <cstdint>
#include <string>

#include "convert.hpp"
#include "failure.hpp"

#include "color.hpp"
#include "draw_list.hpp"

namespace ds::guile {

// (r g b) or (r g b a), each an exact integer 0–255, or a colour's name.
bool color_arg(SCM v, render::Rgba& out, Failure& f, Arg what = "color");

// world or screen.
bool space_arg(SCM v, render::Space& out, Failure& f);

bool gid_arg(SCM v, const char* what, uint32_t& out, Failure& f);

// A symbol's name.
bool symbol_arg(SCM v, const char* what, std::string& out, Failure& f);

// kNamedColors' names as symbols, in its order.
SCM named_color_symbol(size_t i);

// Interns the symbols above, once, before any procedure converts an argument.
void register_render_arguments();

}  // namespace ds::guile
