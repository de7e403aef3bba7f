// SPDX-License-Identifier: MIT
#include "accuracy/scenes.hpp"

#include "speed/scenes.hpp"

namespace bench::accuracy {

namespace {

ds::Num exact(double v) { return ds::Num::integer(v); }

ds::Body box(double x, double y, double w, double h) {
    ds::Body b;
    b.x = exact(x);
    b.y = exact(y);
    b.w = exact(w);
    b.h = exact(h);
    return b;
}

ds::Body solid_box(double x, double y) {
    ds::Body b = box(x, y, 8, 8);
    b.gravity = b.solid = true;
    return b;
}

// cols × rows cells; `solid(c, r)` says which are.
template <class Solid>
std::shared_ptr<const ds::TileGrid> grid(int cols, int rows, Solid solid) {
    std::vector<uint8_t> cells(static_cast<size_t>(cols) * rows);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) cells[static_cast<size_t>(r) * cols + c] = solid(c, r) ? 1 : 0;
    return std::make_shared<const ds::TileGrid>(cols, rows, kTile, kTile, std::move(cells));
}

// Walls `thick` tiles thick on all four sides.
std::shared_ptr<const ds::TileGrid> walled(int cols, int rows, int thick) {
    return grid(cols, rows, [&](int c, int r) {
        return c < thick || r < thick || c >= cols - thick || r >= rows - thick;
    });
}

constexpr int kFloorRow = 10;    // jump_floor: the floor's row
constexpr int kWallCol = 33;     // tunnel_lane: the wall's column
constexpr int kStackRows = 12;   // stack: the floor is the last row

}  // namespace

ds::World Setup::world() const {
    ds::World w;
    w.bodies = bodies;
    w.grid = grid.get();
    return w;
}

Setup jump_free() {
    ds::Body b = box(0, 0, kJumpBox, kJumpBox);
    b.vy = exact(kJumpSpeed);
    b.gravity = true;
    return {"jump", nullptr, {b}};
}

double jump_floor_y() { return kFloorRow * kTile; }

Setup jump_floor() {
    ds::Body b = box(kTile, jump_floor_y() - kJumpBox, kJumpBox, kJumpBox);
    b.vy = exact(kJumpSpeed);
    b.gravity = b.on_ground = true;
    return {"landing", grid(3, kFloorRow + 1, [](int, int r) { return r == kFloorRow; }), {b}};
}

double tunnel_wall_x() { return kWallCol * kTile; }

std::vector<int> tunnel_speeds(int max_speed) {
    std::vector<int> speeds;
    for (int v = 1; v <= max_speed; ++v) speeds.insert(speeds.end(), static_cast<size_t>(v), v);
    return speeds;
}

Setup tunnel_lane(int max_speed) {
    Setup s{"tunnel", grid(kWallCol + 1, 1, [](int c, int) { return c == kWallCol; }), {}};
    // In tunnel_speeds' order: by speed, then the gap to the wall, 1 … v px.
    for (int v = 1; v <= max_speed; ++v)
        for (int d = 0; d < v; ++d) {
            ds::Body b = box(tunnel_wall_x() - 8 - 1 - d, 4, 8, 8);
            b.vx = exact(v);
            s.bodies.push_back(b);
        }
    return s;
}

Setup arena(int n) {
    constexpr int kCols = 44, kRows = 28, kThick = 2;
    constexpr double kFloorY = (kRows - kThick) * kTile;
    constexpr int kPerRow = 36;
    Setup s{"arena", walled(kCols, kRows, kThick), {}};
    for (int i = 0; i < n; ++i) {
        ds::Body b = solid_box(kThick * kTile + 4 + 16 * (i % kPerRow), 40 + 12 * (i / kPerRow));
        b.vx = exact(i % 5 - 2);
        s.bodies.push_back(b);
    }
    for (int j = 0; j < 4; ++j) {
        ds::Body p = box(96 + 128 * j, kFloorY - 48, 16, 48);
        p.solid = p.immovable = true;
        s.bodies.push_back(p);
    }
    return s;
}

Setup drop() {
    constexpr int kCols = 24, kRows = 24, kThick = 2, kColumns = 8, kHeight = 6;
    constexpr double kLeft = kThick * kTile, kRight = (kCols - kThick) * kTile;
    constexpr double kFloorY = (kRows - kThick) * kTile;
    Setup s{"drop", walled(kCols, kRows, kThick), {}};
    for (int c = 0; c < kColumns; ++c) {
        const bool left = c < kColumns / 2;
        // The outermost columns start against the walls; boxes shift away from them.
        const double x = left ? kLeft + 44 * c : kRight - 8 - 44 * (kColumns - 1 - c);
        for (int j = 0; j < kHeight; ++j) {
            const double shift = (j % 3) * 3 * (left ? 1 : -1);
            // The gap above box j−1 grows with j (10, 30, 50 … px): each lands faster.
            s.bodies.push_back(solid_box(x + shift, kFloorY - 8 - j * (8 + 10 * j)));
        }
    }
    return s;
}

Setup stack(int height) {
    constexpr double kFloorY = (kStackRows - 1) * kTile;
    Setup s{"stack", grid(4, kStackRows, [](int, int r) { return r == kStackRows - 1; }), {}};
    for (int i = 0; i < height; ++i) s.bodies.push_back(solid_box(20, kFloorY - 8 * (i + 1)));
    return s;
}

Setup resting_crowd(int n) {
    const Scene scene = make_scene("crowd", n);
    Setup s{"crowd", nullptr, {}};
    s.grid = std::make_shared<const ds::TileGrid>(scene.cols, scene.rows, scene.tile, scene.tile, scene.solid);
    for (const SceneBody& sb : scene.bodies) {
        ds::Body b = box(static_cast<double>(sb.x), static_cast<double>(sb.y), static_cast<double>(sb.w),
                         static_cast<double>(sb.h));
        b.gravity = sb.gravity;
        b.solid = sb.solid;
        b.immovable = sb.immovable;
        b.on_ground = sb.on_ground;
        s.bodies.push_back(b);
    }
    return s;
}

}  // namespace bench::accuracy
