// SPDX-License-Identifier: MIT
// downstroke-bench draw: how long the renderer takes to draw one frame of a
// large map with many sprites (draw/scenes.hpp), in four cases: the scene,
// every sprite in view, the same view on maps of three sizes, and the debug
// overlay on. Built only with the renderer (SDL2).
//
//   downstroke-bench draw [--frames F] [--warmup W] [--rounds R] [--org FILE]
//
// Prints the table and the goals met or missed, and writes the "Drawing"
// section of docs/benchmarks.org. Exits 0 whether or not the goals are met.
#pragma once

namespace bench {

// argv[1] is "draw".
int draw_main(int argc, char** argv);

}  // namespace bench
