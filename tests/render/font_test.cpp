// SPDX-License-Identifier: MIT
// The built-in 5 × 7 bitmap font: glyph_row() for printable ASCII, '?' for
// anything else, and glyphs that are blank only for space and never alike.
#include <doctest/doctest.h>

#include <array>
#include <climits>
#include <cstdint>
#include <vector>

#include "font.hpp"

using ds::render::glyph_row;
using ds::render::kGlyphHeight;
using ds::render::kGlyphWidth;

namespace {

using Rows = std::array<uint8_t, kGlyphHeight>;

Rows glyph(unsigned char c) {
    Rows rows{};
    for (int r = 0; r < kGlyphHeight; ++r) rows[r] = glyph_row(c, r);
    return rows;
}

}  // namespace

TEST_SUITE("font") {

TEST_CASE("space is blank") {
    for (int r = 0; r < kGlyphHeight; ++r) CHECK(glyph_row(' ', r) == 0);
}

TEST_CASE("every printable character but space has ink") {
    for (int c = 33; c <= 126; ++c) {
        CAPTURE(c);
        bool ink = false;
        for (int r = 0; r < kGlyphHeight; ++r) ink = ink || glyph_row(c, r) != 0;
        CHECK(ink);
    }
}

TEST_CASE("a byte outside 32-126 draws as '?'") {
    const Rows question = glyph('?');
    for (int c : {0, 10, 31, 127, 200, 255}) {
        CAPTURE(c);
        CHECK(glyph(static_cast<unsigned char>(c)) == question);
    }
    CHECK(glyph('A') != question);  // and a printable one does not
}

TEST_CASE("a row outside the glyph is blank") {
    for (int r : {-1, kGlyphHeight, 8, 100, INT_MIN, INT_MAX}) {
        CAPTURE(r);
        CHECK(glyph_row('H', r) == 0);
        CHECK(glyph_row('#', r) == 0);
        CHECK(glyph_row(200, r) == 0);
    }
}

TEST_CASE("'A' and 'H' are the glyphs drawn in font.cpp") {
    CHECK(glyph('A') == Rows{0b01110, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001});
    CHECK(glyph('H') == Rows{0b10001, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001});
}

TEST_CASE("the high bit is the leftmost pixel") {
    CHECK(glyph_row('L', 0) == 0b10000);  // L's stem is on the left
    CHECK(glyph_row('L', 6) == 0b11111);
    CHECK(glyph_row('/', 0) == 0b00001);  // '/' starts at the top right
    CHECK(glyph_row('\\', 0) == 0b10000);
}

TEST_CASE("no glyph sets a bit outside kGlyphWidth") {
    const unsigned mask = (1u << kGlyphWidth) - 1;
    for (int c = 0; c <= 255; ++c)
        for (int r = 0; r < kGlyphHeight; ++r) {
            CAPTURE(c);
            CAPTURE(r);
            CHECK((glyph_row(c, r) & ~mask) == 0);
        }
}

TEST_CASE("the 94 printable glyphs other than space are pairwise distinct") {
    std::vector<Rows> glyphs;
    for (int c = 33; c <= 126; ++c) glyphs.push_back(glyph(c));
    REQUIRE(glyphs.size() == 94);
    for (std::size_t i = 0; i < glyphs.size(); ++i)
        for (std::size_t j = i + 1; j < glyphs.size(); ++j) {
            CAPTURE(char(33 + i));
            CAPTURE(char(33 + j));
            CHECK(glyphs[i] != glyphs[j]);
        }
}

}  // TEST_SUITE
