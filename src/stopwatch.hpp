// Wall time for the per-step figures of FrameStats (engine-stats).
#pragma once
#include <chrono>

namespace ds {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace ds
