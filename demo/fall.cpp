// SPDX-License-Identifier: 0BSD
// Headless: loads a Tiled level, drops a few bodies onto it and prints where
// they are every few frames, until all of them stand on something.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <downstroke/downstroke.hpp>

namespace {

ds::Body falling_box(double x, double y, double vx) {
    ds::Body b;
    b.x = ds::Num::integer(x);
    b.y = ds::Num::integer(y);
    b.w = ds::Num::integer(12);
    b.h = ds::Num::integer(14);
    b.vx = ds::Num::integer(vx);
    b.gravity = true;
    b.solid = true;
    return b;
}

void print_bodies(int frame, const ds::World& world) {
    std::printf("frame %3d:", frame);
    for (const ds::Body& b : world.bodies)
        std::printf("  (%g, %g)%s", b.x.v, b.y.v, b.on_ground ? " ground" : "");
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    const std::string level = argc > 1 ? argv[1] : DS_DEMO_DIR "/maps/level1.tmx";
    try {
        const ds::Tilemap map = ds::load_tilemap(level);
        const ds::TileGrid grid = map.solid_grid();
        std::printf("%s: %dx%d cells of %dx%d px\n", level.c_str(), map.width, map.height,
                    map.tile_width, map.tile_height);

        ds::World world;
        world.grid = &grid;
        world.bodies = {falling_box(40, 0, 0), falling_box(100, 10, 2), falling_box(200, 0, -3),
                        falling_box(42, -40, 0)};
        ds::Frame frame;
        for (int f = 1; f <= 120; ++f) {
            frame.step(world, {});
            bool resting = true;
            for (const ds::Body& b : world.bodies) resting = resting && b.on_ground;
            if (f % 10 == 0 || resting) print_bodies(f, world);
            if (resting) {
                std::printf("all %zu bodies on the ground after %d frames\n", world.bodies.size(), f);
                return EXIT_SUCCESS;
            }
        }
        std::printf("bodies still moving after 120 frames\n");
        return EXIT_SUCCESS;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "downstroke-fall: %s\n", e.what());
        return EXIT_FAILURE;
    }
}
