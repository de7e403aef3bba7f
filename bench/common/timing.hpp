// SPDX-License-Identifier: MIT
// Clocks, per-frame statistics, and the frame-time estimates that decide
// how many frames to run and what to skip.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace bench {

int64_t now_ns();  // steady clock

struct Stats {
    double median_ms = 0, p95_ms = 0, mean_ms = 0, min_ms = 0, max_ms = 0;
};
Stats summarize(std::vector<double> frame_ms);

// Watches a run frame by frame (warm-up frames included): stops it at once
// when one frame took longer than max_frame_ms (a skip, with a reason), and
// once the frames so far add up to budget_ms, provided `min_timed` timed
// frames are in.
class FrameGuard {
public:
    FrameGuard(double max_frame_ms, double budget_ms, int min_timed = 3)
        : max_frame_ms_(max_frame_ms), budget_ms_(budget_ms), min_timed_(min_timed) {}
    bool keep_going(double frame_ms, int timed_so_far);
    const std::string& skip_reason() const { return skip_; }

private:
    double max_frame_ms_, budget_ms_, total_ms_ = 0;
    int min_timed_;
    std::string skip_;
};

std::string too_slow(double frame_ms, double max_frame_ms);

// Past frame times of one (scene, path) series, by N: predicts the time of
// one frame at a larger N by extrapolating the growth between the last two
// measured sizes (exponent clamped to [1, 2.2]; quadratic with one point),
// with a safety factor of 2.
class Estimator {
public:
    void record(const std::string& series, int n, double frame_ms);
    bool has(const std::string& series, int n) const;
    // < 0 when nothing is known about the series.
    double estimate(const std::string& series, int n) const;

private:
    std::map<std::string, std::map<int, double>> points_;
};

}  // namespace bench
