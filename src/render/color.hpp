// A colour with alpha, as game code names it: 0–255 per channel.
#pragma once
#include <cstdint>

namespace ds::render {

struct Rgba {
    uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

}  // namespace ds::render
