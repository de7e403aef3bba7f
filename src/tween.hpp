// SPDX-License-Identifier: MIT
// Tweens: a body's properties driven from start to end values over time.
// The timing is pure data; the caller stores a tween next to its entity.
#pragma once
#include <cstdint>
#include <vector>

#include "ease.hpp"
#include "number.hpp"
#include "export.hpp"

namespace ds {

struct TweenProp {
    uint32_t key = 0;  // a Key (tween.hpp users map their own names to ids)
    Num start, end;
};

struct TweenTiming {
    double duration = 0;  // ms per cycle
    double delay = 0;     // ms before the first cycle only
    int64_t repeat = 0;   // extra cycles; −1 repeats forever
    bool yoyo = false;    // odd cycles run end → start
};

// Where a tween stands after `elapsed` ms.
struct TweenPhase {
    bool started = false;   // past the delay: properties are written
    bool finished = false;  // the last cycle is over: write targets, drop the tween
    bool reversed = false;  // this cycle runs end → start (yoyo)
    double t = 0;           // progress through the cycle, in [0, 1]
};

// Where a tween stands after `elapsed` ms (semantics §6).
DOWNSTROKE_API TweenPhase tween_phase(const TweenTiming& timing, double elapsed);

// The value a property takes at a phase, given ease(t). Intermediate values
// are flonums; once finished it is the final target itself, exactness and all (semantics §6).
DOWNSTROKE_API Num tween_value(const TweenProp& p, const TweenPhase& phase, double eased);

}  // namespace ds
