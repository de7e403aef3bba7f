// SPDX-License-Identifier: MIT
#include "tween.hpp"

#include <algorithm>
#include <cmath>

namespace ds {

TweenPhase tween_phase(const TweenTiming& timing, double elapsed) {
    TweenPhase p;
    if (elapsed < timing.delay) return p;
    p.started = true;
    const double run = elapsed - timing.delay;
    const bool forever = timing.repeat < 0;
    const double cycles = forever ? 0 : static_cast<double>(timing.repeat) + 1;
    if (timing.duration <= 0 || (!forever && run >= cycles * timing.duration)) {
        // The last cycle's direction decides which end is the final target.
        const double last = forever ? 0 : cycles - 1;
        p.finished = true;
        p.reversed = timing.yoyo && std::fmod(last, 2) == 1;
        p.t = 1;
        return p;
    }
    const double cycle = std::floor(run / timing.duration);
    p.reversed = timing.yoyo && std::fmod(cycle, 2) == 1;
    p.t = std::clamp((run - cycle * timing.duration) / timing.duration, 0.0, 1.0);
    return p;
}

Num tween_value(const TweenProp& prop, const TweenPhase& phase, double eased) {
    const Num from = phase.reversed ? prop.end : prop.start;
    const Num to = phase.reversed ? prop.start : prop.end;
    if (phase.finished) return to;
    return Num::flonum(from.v + (to.v - from.v) * eased);
}

}  // namespace ds
