// SPDX-License-Identifier: MIT
// Small builders and checks shared by the core test suites.
#pragma once
#include <doctest/doctest.h>

#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "body.hpp"
#include "number.hpp"
#include "tile_grid.hpp"

namespace dst {

using ds::Body;
using ds::Num;

inline Num I(double v) { return Num::integer(v); }  // an exact integer
inline Num F(double v) { return Num::flonum(v); }   // a flonum

// A body with an exact box and everything else at its defaults.
inline Body box(double x, double y, double w, double h) {
    Body b;
    b.x = I(x);
    b.y = I(y);
    b.w = I(w);
    b.h = I(h);
    return b;
}

inline Body solid_box(double x, double y, double w, double h) {
    Body b = box(x, y, w, h);
    b.solid = true;
    return b;
}

inline Body wall_box(double x, double y, double w, double h) {  // solid and immovable
    Body b = solid_box(x, y, w, h);
    b.immovable = true;
    return b;
}

// Every Num and flag of two bodies identical (ds::same on each Num).
inline bool same_body(const Body& a, const Body& b) {
    return ds::same(a.x, b.x) && ds::same(a.y, b.y) && ds::same(a.w, b.w) &&
           ds::same(a.h, b.h) && ds::same(a.vx, b.vx) && ds::same(a.vy, b.vy) &&
           ds::same(a.ay, b.ay) && ds::same(a.local_x, b.local_x) &&
           ds::same(a.local_y, b.local_y) && a.gravity == b.gravity &&
           a.on_ground == b.on_ground && a.solid == b.solid && a.immovable == b.immovable &&
           a.group_origin == b.group_origin && a.skip == b.skip && a.id == b.id &&
           a.group == b.group && a.category == b.category && a.collides_with == b.collides_with &&
           a.sensor == b.sensor && a.bounce == b.bounce;
}

// A grid drawn as text: one string per row, '#' solid, anything else empty.
inline ds::TileGrid grid(const std::vector<std::string>& rows, int tw = 16, int th = 16,
                         int64_t origin_col = 0, int64_t origin_row = 0) {
    const int cols = rows.empty() ? 0 : static_cast<int>(rows[0].size());
    std::vector<uint8_t> mask;
    for (const auto& r : rows) {
        REQUIRE(static_cast<int>(r.size()) == cols);
        for (char c : r) mask.push_back(c == '#' ? 1 : 0);
    }
    return ds::TileGrid(cols, static_cast<int>(rows.size()), tw, th, std::move(mask), origin_col,
                        origin_row);
}

// The nine skip bits, for loops over all of them.
inline constexpr uint16_t kAllSkips[] = {
    ds::kSkipAcceleration, ds::kSkipGravity, ds::kSkipVelocityX,
    ds::kSkipVelocityY,    ds::kSkipTileX,   ds::kSkipTileY,
    ds::kSkipOnSolid,      ds::kSkipEntityCollisions, ds::kSkipTweens,
    ds::kSkipCarry,        ds::kSkipSpeedLimits,
};
static_assert(std::size(kAllSkips) == ds::kSkipCount, "a Skip bit is missing here");
inline constexpr uint16_t kEverySkip = (1u << ds::kSkipCount) - 1;

}  // namespace dst

// Value and exactness of a Num in one line (keeps the failing line number).
#define CHECK_EXACT(num, value)            \
    do {                                   \
        const ::ds::Num n_ = (num);        \
        CHECK(n_.v == (value));            \
        CHECK_MESSAGE(n_.exact, #num " should be an exact integer"); \
    } while (0)
#define CHECK_FLONUM(num, value)           \
    do {                                   \
        const ::ds::Num n_ = (num);        \
        CHECK(n_.v == (value));            \
        CHECK_MESSAGE(!n_.exact, #num " should be a flonum"); \
    } while (0)
#define CHECK_FLONUM_APPROX(num, value)    \
    do {                                   \
        const ::ds::Num n_ = (num);        \
        CHECK(n_.v == doctest::Approx(value)); \
        CHECK_MESSAGE(!n_.exact, #num " should be a flonum"); \
    } while (0)
