// SPDX-License-Identifier: MIT
// The built-in bitmap font, so text can be drawn with no font file: printable
// ASCII (32–126), each glyph 5 px wide and 7 px tall, set in a 6 × 9 cell.
#pragma once
#include <cstdint>

namespace ds::render {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;  // one column of space between letters
constexpr int kLineHeight = 9;    // two rows between lines: room for descenders' tails

// Row `row` (0 = top, < kGlyphHeight) of the glyph for byte c: bit
// (kGlyphWidth - 1 - x) is set where pixel x is ink. A byte outside 32–126
// draws as '?'.
uint8_t glyph_row(unsigned char c, int row);

}  // namespace ds::render
