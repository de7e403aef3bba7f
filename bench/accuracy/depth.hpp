// SPDX-License-Identifier: MIT
// How deep a body sits in what it must not enter, as the accuracy bench's
// penetration columns and its sinking table both measure it.
#pragma once
#include "body.hpp"
#include "tile_grid.hpp"

namespace bench::accuracy {

// The overlap of [p1, p1 + s1) and [p2, p2 + s2) (negative when apart).
double overlap(double p1, double s1, double p2, double s2);
// The deepest the body sits in one whole solid cell: per cell, the smaller
// axis overlap.
double depth_in_tiles(const ds::Body& b, const ds::TileGrid& g);

}  // namespace bench::accuracy
