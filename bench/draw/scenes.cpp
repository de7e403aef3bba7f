// SPDX-License-Identifier: MIT
#include "draw/scenes.hpp"

#include <cstdint>
#include <string>

#include "tilemap/object_index.hpp"

namespace bench::draw {

namespace {

using ds::render::EntityView;

// A well-mixed 64-bit value of v (splitmix64's finaliser): the same on every
// platform, unlike the standard distributions.
uint64_t mix(uint64_t v) {
    v += 0x9e3779b97f4a7c15u;
    v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9u;
    v = (v ^ (v >> 27)) * 0x94d049bb133111ebu;
    return v ^ (v >> 31);
}

// Of the seven non-empty combinations of the three flip bits, by h.
uint32_t flips(uint64_t h) {
    const uint32_t combo = uint32_t(h % 7) + 1;
    return (combo & 1 ? ds::kFlipHorizontal : 0) | (combo & 2 ? ds::kFlipVertical : 0) |
           (combo & 4 ? ds::kFlipDiagonal : 0);
}

// A gid 1–4 from the low bits of h, flipped when bits 8–9 are zero (a quarter).
uint32_t gid(uint64_t h) { return (1 + uint32_t(h & 3)) | ((h >> 8 & 3) == 0 ? flips(h >> 16) : 0); }

ds::TileLayer layer(const char* name, int side) {
    ds::TileLayer l;
    l.name = name;
    l.width = l.height = side;
    l.cells.resize(size_t(side) * side);
    return l;
}

}  // namespace

ds::Tilemap make_map(int side) {
    ds::Tilemap m;
    m.width = m.height = side;
    m.tile_width = m.tile_height = kTile;
    ds::Tileset ts;
    ts.firstgid = 1;
    ts.name = "tiles";
    ts.tile_width = ts.tile_height = kTile;
    ts.tile_count = ts.columns = 4;
    ts.image = "tiles.png";
    ts.image_width = 4 * kTile;
    ts.image_height = kTile;
    ts.image_dir = DS_BENCH_MAPS_DIR;
    m.tilesets.push_back(ts);
    ds::TileLayer ground = layer("ground", side), detail = layer("detail", side);
    for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c) {
            const uint64_t h = mix(uint64_t(r) << 32 | uint32_t(c));
            const size_t i = size_t(r) * side + c;
            ground.cells[i] = gid(h);
            if ((h >> 40 & 3) == 0) detail.cells[i] = gid(h >> 24);
        }
    m.layers.push_back(std::move(ground));
    m.layers.push_back(std::move(detail));
    return m;
}

ds::Tilemap make_tiled_map(int side, int out_of_view) {
    ds::Tilemap m = make_map(side);
    ds::LayerInfo backdrop;
    backdrop.kind = ds::LayerKind::Image;
    backdrop.name = "backdrop";
    backdrop.image = std::string(DS_BENCH_MAPS_DIR) + "/backdrop.png";
    backdrop.repeat_x = backdrop.repeat_y = true;
    backdrop.parallax_x = backdrop.parallax_y = 0.2;
    ds::LayerInfo ground;
    ground.kind = ds::LayerKind::Tile;
    ground.name = "ground";
    ground.index = 0;
    ds::LayerInfo detail = ground;
    detail.name = "detail";
    detail.index = 1;
    detail.parallax_x = detail.parallax_y = 0.5;
    ds::LayerInfo things;
    things.kind = ds::LayerKind::Object;
    things.name = "things";
    m.layer_tree = {backdrop, ground, detail, things};
    ds::ObjectLayer layer;
    layer.name = "things";
    const int total = kTileObjects + out_of_view;
    layer.objects.reserve(size_t(total));
    for (int i = 0; i < total; ++i) {
        const uint64_t h = mix(0x0b1ec7000000u + uint64_t(i));
        ds::MapObject o;
        o.id = i + 1;
        o.shape = ds::ObjectShape::Tile;
        o.gid = gid(h);
        o.width = o.height = kTile;
        if ((h >> 40) % 5 == 0) o.width = 24, o.height = 32;  // stretched
        if ((h >> 44) % 10 == 0) o.rotation = double((h >> 48) % 360);
        // In view: over the first kObjectArea px square; beyond: past the
        // map's far corner, where the camera never goes.
        const double far = i < kTileObjects ? 0 : double(side) * kTile + 1000;
        o.x = far + double(h & 0xffffff) / 0x1000000 * kObjectArea;
        o.y = far + double(h >> 24 & 0xffff) / 0x10000 * kObjectArea;
        layer.objects.push_back(std::move(o));
    }
    m.object_layers.push_back(std::move(layer));
    m.object_layers[0].index = ds::index_objects(m, m.object_layers[0]);
    return m;
}

std::vector<EntityView> spread_sprites(int count, double w, double h) {
    std::vector<EntityView> out(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        const uint64_t r = mix(0x5eed0000u + uint64_t(i));
        EntityView& e = out[size_t(i)];
        // Fractions of the area from 24 bits each; positions need not be whole.
        e.x = double(r & 0xffffff) / 0x1000000 * w;
        e.y = double(r >> 24 & 0xffffff) / 0x1000000 * h;
        e.w = e.h = kTile;
        e.sprite = 1 + uint32_t(i % 4);
        e.flip_x = i % 3 == 0;
        e.vx = double(int(r >> 48 & 7) - 3);
        e.vy = double(int(r >> 52 & 3) - 1);
        e.solid = i % 2 == 0;
        e.immovable = i % 10 == 0;
        e.on_ground = e.vy == 0;
    }
    return out;
}

std::vector<EntityView> view_sprites(int count) {
    std::vector<EntityView> out = spread_sprites(count, kViewW - kTile - 2, kViewH - kTile - 2);
    for (EntityView& e : out) e.x += 1, e.y += 1;
    return out;
}

Camera camera_at(int i, int n, double w, double h) {
    const double t = (i + 0.5) / n;
    return {t * (w - kViewW), t * (h - kViewH)};
}

void pin_to_view(std::vector<EntityView>& sprites, const std::vector<EntityView>& offsets, Camera cam) {
    for (size_t i = 0; i < sprites.size(); ++i) {
        sprites[i].x = cam.x + offsets[i].x;
        sprites[i].y = cam.y + offsets[i].y;
    }
}

}  // namespace bench::draw
