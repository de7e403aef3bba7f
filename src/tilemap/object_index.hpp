// SPDX-License-Identifier: MIT
// Where an object layer's tile objects are drawn, indexed by area, so that
// drawing a view visits only the objects that can show in it: a layer of a
// million objects costs a frame what the ones in view cost.
#pragma once
#include <cstdint>
#include <vector>
#include "../export.hpp"

namespace ds {

struct Tilemap;
struct ObjectLayer;

// Buckets of kObjectBucketPx × kObjectBucketPx map px over the drawn
// pictures' bounds (rotation and tile offsets included), each listing the
// objects whose picture touches it, in draw order; and each object's rank
// in the layer's draw order.
struct ObjectIndex {
    double left = 0, top = 0;   // map px of bucket (0, 0)'s corner
    double bucket = 0;          // its side, px
    int64_t cols = 0, rows = 0;
    std::vector<uint32_t> starts;  // cols × rows + 1 offsets into items
    std::vector<uint32_t> items;   // draw ranks, ascending within a bucket
    std::vector<uint32_t> order;   // draw rank → index into the layer's objects
    bool built = false;
};

// The layer's objects in the order they are drawn: its file's, or by y
// (stable) for draworder="topdown"; as indexes into layer.objects.
DOWNSTROKE_API std::vector<uint32_t> object_draw_order(const ObjectLayer& layer);

// The index of `layer` of `map`: its tile objects (hidden ones too: an
// object's visible can change, the index need not), in its draw order
// (file order, or by y for topdown).
DOWNSTROKE_API ObjectIndex index_objects(const Tilemap& map, const ObjectLayer& layer);

// The draw ranks of the objects whose pictures may touch the view [x0, x1)
// × [y0, y1) (map px), ascending and without repeats, into `out` (cleared).
DOWNSTROKE_API void objects_in_view(const ObjectIndex& index, double x0, double y0, double x1, double y1,
                     std::vector<uint32_t>& out);

}  // namespace ds
