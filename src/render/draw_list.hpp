// SPDX-License-Identifier: MIT
// What a game's render hook asked to draw this frame, as plain data: the
// bindings fill it, the canvas draws it after the map and the entities.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "color.hpp"

namespace ds::render {

// World coordinates move with the camera; screen coordinates do not (a HUD).
enum class Space : uint8_t { World, Screen };

struct DrawCommand {
    enum class Kind : uint8_t { Rect, FilledRect, Line, Sprite, Text };
    Kind kind = Kind::Rect;
    Space space = Space::World;
    double x = 0, y = 0;
    double x2 = 0, y2 = 0;  // Rect/FilledRect: width and height; Line: the end point
    Rgba color;
    uint32_t gid = 0;       // Sprite: a raw gid, flip bits honoured
    int scale = 1;          // Text: each font pixel is scale × scale
    std::string text = {};
};

struct DrawList {
    std::vector<DrawCommand> commands;
    void clear() { commands.clear(); }
};

}  // namespace ds::render
