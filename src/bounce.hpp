// SPDX-License-Identifier: MIT
// Bounce (semantics §13): the velocity a stop leaves on its axis. Without
// #:bounce it is 0, the seed's rule; with it, the velocity turned back and
// scaled, so a ball rebounds from a wall and a grenade from the floor.
#pragma once
#include <cmath>

#include "body.hpp"
#include "constants.hpp"

namespace ds {

// −v·bounce, or 0 when bounce is 0 or the hit is no faster than
// kBounceRestSpeed (a body at rest stays at rest). Exact when v and bounce
// are (bounce 1: exactly −v); otherwise a flonum.
inline Num rebound(Num v, Num bounce) {
    if (bounce.v == 0 || !(std::fabs(v.v) > kBounceRestSpeed)) return Num::integer(0);
    return Num{-(v.v * bounce.v), v.exact && bounce.exact};
}
inline Num rebound(Num v, UnitNum bounce) { return rebound(v, bounce.num()); }

// A pair's bounce: the larger of the two (on a tie, the first's).
inline Num pair_bounce(const Body& a, const Body& b) {
    return b.bounce.value() > a.bounce.value() ? b.bounce.num() : a.bounce.num();
}

}  // namespace ds
