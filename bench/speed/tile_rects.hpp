// SPDX-License-Identifier: MIT
// A scene's solid cells as few boxes as the Box2D paths build them from
// (no Box2D types here, so the 2.4 and v3 paths, compiled against
// different headers, share it).
#pragma once
#include <vector>

#include "speed/scenes.hpp"

namespace bench {

struct Rect {
    int c0, c1, r0, r1;  // cells, inclusive
};

// Runs of solid cells per row, merged downwards while the next row has the
// very same run: a floor several tiles deep is one box, a wall one column.
std::vector<Rect> tile_rects(const Scene& s);

}  // namespace bench
