// SPDX-License-Identifier: MIT
#include "accuracy/depth.hpp"

#include <algorithm>

namespace bench::accuracy {

double overlap(double p1, double s1, double p2, double s2) {
    return std::min(p1 + s1, p2 + s2) - std::max(p1, p2);
}

double depth_in_tiles(const ds::Body& b, const ds::TileGrid& g) {
    const ds::CellRange cols = g.clip_cols(ds::cells_of(b.x, b.w, g.tile_width()));
    const ds::CellRange rows = g.clip_rows(ds::cells_of(b.y, b.h, g.tile_height()));
    const double tw = g.tile_width(), th = g.tile_height();
    double deepest = 0;
    for (int64_t r = rows.first; r <= rows.last; ++r)
        for (int64_t c = cols.first; c <= cols.last; ++c)
            if (g.solid(c, r))
                deepest = std::max(deepest, std::min(overlap(b.x.v, b.w.v, static_cast<double>(c) * tw, tw),
                                                     overlap(b.y.v, b.h.v, static_cast<double>(r) * th, th)));
    return deepest;
}

}  // namespace bench::accuracy
