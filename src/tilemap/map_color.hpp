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

// Whether a layer's tintcolor= is one Tiled leaves unread: it reads the
// tint as Qt reads a colour name (QColor(QString)), hex only after a '#',
// so "ff0000" is no colour to it and the layer is drawn untinted
// (Layer::effectiveTintColor). The engine does the same, with a warning.
inline bool tint_without_hash(std::string_view text) { return !text.empty() && text.front() != '#'; }

}  // namespace ds
