// SPDX-License-Identifier: MIT
#include "map_objects.hpp"


namespace ds {

ObjectShape object_kind(uint32_t gid, ObjectShape shape) { return gid != 0 ? ObjectShape::Tile : shape; }

std::pair<double, double> tile_picture_size(const Tilemap& map, uint32_t gid) {
    gid &= kGidMask;
    const Tileset* ts = gid ? map.tileset_for(gid) : nullptr;
    if (!ts) return {0, 0};
    if (ts->image_collection()) {
        const TileInfo* t = ts->tile(gid - ts->firstgid);
        return t ? std::pair<double, double>{t->image_width, t->image_height} : std::pair<double, double>{0, 0};
    }
    return {ts->tile_width, ts->tile_height};
}

namespace {

// The box's point an alignment names, from its top-left corner.
std::pair<double, double> alignment_offset(ObjectAlignment a, double w, double h) {
    switch (a) {
        case ObjectAlignment::TopLeft: return {0, 0};
        case ObjectAlignment::Top: return {w / 2, 0};
        case ObjectAlignment::TopRight: return {w, 0};
        case ObjectAlignment::Left: return {0, h / 2};
        case ObjectAlignment::Center: return {w / 2, h / 2};
        case ObjectAlignment::Right: return {w, h / 2};
        case ObjectAlignment::Bottom: return {w / 2, h};
        case ObjectAlignment::BottomRight: return {w, h};
        case ObjectAlignment::Unspecified:  // orthogonal maps: bottom-left
        case ObjectAlignment::BottomLeft: break;
    }
    return {0, h};
}

}  // namespace

TileObjectBox tile_object_box(const Tilemap& map, const MapObject& o) {
    TileObjectBox b;
    b.width = o.width, b.height = o.height;
    if (b.width == 0 && b.height == 0) std::tie(b.width, b.height) = tile_picture_size(map, o.gid);
    const Tileset* ts = map.tileset_for(o.gid & kGidMask);
    const auto [ax, ay] = alignment_offset(ts ? ts->object_alignment : ObjectAlignment::Unspecified,
                                           b.width, b.height);
    b.left = o.x - ax, b.top = o.y - ay;
    b.pivot_x = o.x, b.pivot_y = o.y, b.rotation = o.rotation;
    return b;
}

}  // namespace ds
