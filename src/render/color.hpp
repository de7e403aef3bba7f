// SPDX-License-Identifier: MIT
// A colour with alpha, as game code names it: 0–255 per channel.
#pragma once
#include <cstdint>
#include <string_view>

namespace ds::render {

struct Rgba {
    uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

// The colours game code may name instead of writing (r g b): the drawing
// procedures' colour argument and an entity's #:color read this one table,
// so a name means the same wherever it is written.
struct NamedColor {
    std::string_view name;
    Rgba rgba;
};
inline constexpr NamedColor kNamedColors[] = {
    {"white", {255, 255, 255}}, {"black", {0, 0, 0}},        {"red", {230, 60, 60}},
    {"green", {80, 220, 100}},  {"blue", {80, 150, 255}},    {"yellow", {250, 220, 70}},
    {"cyan", {90, 220, 240}},   {"magenta", {220, 90, 220}}, {"orange", {255, 150, 40}},
    {"grey", {150, 150, 150}},  {"gray", {150, 150, 150}}};

// a · b / 255, rounded to the nearest: a channel scaled by another (a tint,
// an alpha).
constexpr uint8_t mul255(unsigned a, unsigned b) { return static_cast<uint8_t>((a * b + 127) / 255); }

}  // namespace ds::render
