// SPDX-License-Identifier: MIT
#include "map_color.hpp"

namespace ds {

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

std::optional<MapColor> parse_map_color(std::string_view text) {
    if (!text.empty() && text.front() == '#') text.remove_prefix(1);
    if (text.size() != 6 && text.size() != 8) return std::nullopt;
    uint8_t bytes[4] = {255, 0, 0, 0};
    const size_t first = text.size() == 8 ? 0 : 1;  // no alpha written: opaque
    for (size_t i = 0; i < text.size(); i += 2) {
        const int hi = hex_digit(text[i]), lo = hex_digit(text[i + 1]);
        if (hi < 0 || lo < 0) return std::nullopt;
        bytes[first + i / 2] = static_cast<uint8_t>(hi * 16 + lo);
    }
    return MapColor{bytes[1], bytes[2], bytes[3], bytes[0]};
}

}  // namespace ds
