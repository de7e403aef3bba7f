// SPDX-License-Identifier: MIT
#include "state_hash.hpp"

#include <bit>

#include "constants.hpp"

namespace ds {

void StateHash::number(Num n) {
    // Exact zero reaches the core as +0.0, but arithmetic could in principle
    // produce -0.0 with the exact flag set; Scheme would write it back as 0.
    const double v = (n.exact && n.v == 0.0) ? 0.0 : n.v;
    byte(n.exact ? 1 : 0);
    const uint64_t bits = std::bit_cast<uint64_t>(v);
    for (int i = 0; i < 8; ++i) byte(static_cast<uint8_t>(bits >> (8 * i)));
}

void StateHash::add(const Body& b) {
    for (const Num n : {b.x, b.y, b.w, b.h, b.vx, b.vy, b.ay}) number(n);
    byte(b.on_ground ? 1 : 0);
}

void StateHash::add_gravity(Num g) {
    if (same(g, Num::integer(kGravity))) return;
    byte(0x47);
    number(g);
}

uint64_t state_hash(std::span<const Body> bodies) {
    StateHash h;
    for (const Body& b : bodies) h.add(b);
    return h.value();
}

}  // namespace ds
