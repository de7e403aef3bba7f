// SPDX-License-Identifier: MIT
// Wall time for the per-step figures of FrameStats (engine-stats).
#pragma once
#include <chrono>

namespace ds {

using Clock = std::chrono::steady_clock;

inline double ms_between(Clock::time_point t0, Clock::time_point t1) {
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

inline double ms_since(Clock::time_point t0) { return ms_between(t0, Clock::now()); }

}  // namespace ds
