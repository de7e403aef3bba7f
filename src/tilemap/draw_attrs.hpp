// SPDX-License-Identifier: MIT
// The named values of the attributes that say how a map is drawn, as Tiled
// writes them in TMX and JSON alike; each parser gives nullopt for a name it
// does not know, and the readers turn that into an error naming the value.
#pragma once
#include <optional>
#include <string_view>

#include "tilemap.hpp"

namespace ds {

// objectalignment=: unspecified, topleft, top, topright, left, center,
// right, bottomleft, bottom, bottomright.
std::optional<ObjectAlignment> parse_object_alignment(std::string_view text);
// tilerendersize=: tile, grid.
std::optional<TileRenderSize> parse_tile_render_size(std::string_view text);
// fillmode=: stretch, preserve-aspect-fit.
std::optional<FillMode> parse_fill_mode(std::string_view text);
// renderorder=: right-down, right-up, left-down, left-up.
std::optional<RenderOrder> parse_render_order(std::string_view text);
// An object layer's draworder=: index (false) or topdown (true).
std::optional<bool> parse_draw_order(std::string_view text);

}  // namespace ds
