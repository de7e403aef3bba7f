// SPDX-License-Identifier: MIT
// A colour as a Tiled map writes it (backgroundcolor=, tintcolor=, an
// image's trans=): "#RRGGBB" or "#AARRGGBB", the '#' optional.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include "../export.hpp"

namespace ds {

struct MapColor {
    uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const MapColor&, const MapColor&) = default;
};

// The colour `text` names, or nullopt when it is not one of the forms above
// (the readers turn that into an error naming the file and the value).
DOWNSTROKE_API std::optional<MapColor> parse_map_color(std::string_view text);

}  // namespace ds
