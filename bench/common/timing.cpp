// SPDX-License-Identifier: MIT
#include "common/timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace bench {

int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

namespace {

// Nearest-rank percentile of sorted values.
double percentile(const std::vector<double>& sorted, double p) {
    if (sorted.empty()) return 0;
    const auto rank = static_cast<size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
    return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

Stats summarize(std::vector<double> ms) {
    Stats s;
    if (ms.empty()) return s;
    std::sort(ms.begin(), ms.end());
    const size_t n = ms.size();
    s.median_ms = n % 2 ? ms[n / 2] : (ms[n / 2 - 1] + ms[n / 2]) / 2;
    s.p95_ms = percentile(ms, 95);
    s.mean_ms = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(n);
    s.min_ms = ms.front();
    s.max_ms = ms.back();
    return s;
}

std::string too_slow(double frame_ms, double max_frame_ms) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "a frame took %.3g s > %.3g s", frame_ms / 1000, max_frame_ms / 1000);
    return buf;
}

bool FrameGuard::keep_going(double frame_ms, int timed_so_far) {
    total_ms_ += frame_ms;
    if (frame_ms > max_frame_ms_) {
        skip_ = too_slow(frame_ms, max_frame_ms_);
        return false;
    }
    return !(total_ms_ > budget_ms_ && timed_so_far >= min_timed_);
}

void Estimator::record(const std::string& series, int n, double frame_ms) {
    points_[series][n] = frame_ms;
}

bool Estimator::has(const std::string& series, int n) const {
    auto it = points_.find(series);
    return it != points_.end() && it->second.count(n) != 0;
}

double Estimator::estimate(const std::string& series, int n) const {
    auto it = points_.find(series);
    if (it == points_.end() || it->second.empty()) return -1;
    const auto& pts = it->second;
    auto hit = pts.find(n);
    if (hit != pts.end()) return hit->second;
    // The largest measured N below n, and the one before it.
    auto above = pts.lower_bound(n);
    if (above == pts.begin()) return -1;  // only larger sizes known: no extrapolation downwards
    auto last = std::prev(above);
    double exponent = 2.0;
    if (last != pts.begin()) {
        auto before = std::prev(last);
        if (before->second > 0 && last->second > 0)
            exponent = std::log(last->second / before->second) /
                       std::log(static_cast<double>(last->first) / before->first);
        exponent = std::clamp(exponent, 1.0, 2.2);
    }
    // Twice the extrapolation: growth tends to steepen (caches, collections).
    return 2 * last->second * std::pow(static_cast<double>(n) / last->first, exponent);
}

}  // namespace bench
