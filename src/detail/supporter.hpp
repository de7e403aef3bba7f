// SPDX-License-Identifier: MIT
// What ground detection reads of a body that can hold others up: its top
// edge, span, vertical speed, id and categories. A frame copies every solid
// body out before any moves; at 64 bytes instead of a whole Body the copy, and the
// scans over it, touch a fraction of the memory.
#pragma once
#include <cstdint>

#include "body.hpp"

namespace ds {

struct Supporter {
    double x = 0, y = 0, w = 0, vy = 0;
    int64_t id = 0;
    uint64_t category = 1, collides_with = ~uint64_t{0};  // holds up only bodies it meets (§13)
    bool one_way = false;  // holds up only bodies not rising nor dropping through

    // Only for a body that collides (Body::collides): others hold nobody up.
    static Supporter of(const Body& b) {
        return {b.x.v, b.y.v, b.w.v, b.vy.v, b.id, b.category.bits(), b.collides_with.bits, b.one_way};
    }
    bool meets(const Body& b) const {
        return categories_meet(category, collides_with, b.category.bits(), b.collides_with.bits);
    }
};

}  // namespace ds
