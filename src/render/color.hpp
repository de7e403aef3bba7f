// A colour with alpha, as game code names it: 0–255 per channel.
#pragma once
#include <cstdint>

namespace ds::render {

struct Rgba {
    uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

// a · b / 255, rounded to the nearest: a channel scaled by another (a tint,
// an alpha).
constexpr uint8_t mul255(unsigned a, unsigned b) { return static_cast<uint8_t>((a * b + 127) / 255); }

}  // namespace ds::render
