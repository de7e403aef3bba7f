// SPDX-License-Identifier: MIT
// A drawn frame against a golden picture (a PNG written earlier): which
// pixels differ, and pictures that show it. What (downstroke testing)'s
// check-frame stands on.
#pragma once
#include <cstdint>
#include <string>

#include "canvas.hpp"
#include "color.hpp"

namespace ds::render {

struct FrameDiff {
    bool same_size = true;
    int golden_width = 0, golden_height = 0;
    int64_t differing = 0;          // pixels whose r, g, b or a differ
    int first_x = -1, first_y = -1;  // the first, in reading order
    Rgba expected{}, actual{};       // its colours
};

// Compares `canvas` with the PNG at `golden` (read as any picture is,
// image_header.hpp's bounds included). When they differ, writes the canvas
// to `actual_png` and to `diff_png` a picture of the same size, each pixel
// that differs magenta and the rest the frame darkened to a third. Throws
// RenderError naming the file when the golden picture cannot be read.
FrameDiff compare_with_png(const Canvas& canvas, const std::string& golden, const std::string& actual_png,
                           const std::string& diff_png);

}  // namespace ds::render
