// SPDX-License-Identifier: MIT
// One combination of scene × N × path: its repetitions, each from a fresh
// world, under a shared time budget.
#pragma once
#include <string>

#include "speed/paths.hpp"

namespace bench {

struct Repeated {
    PathResult result;  // the timed frames of every repetition, pooled
    int reps = 0;       // repetitions run
};

// One repetition on `path` (guile, native, bare, reference, box2d, box2d-discrete, box2d3, box2d3-2).
PathResult run_path(const std::string& path, const Scene& scene, const RunConfig& cfg);

// Up to `reps` repetitions; stops repeating once cfg.budget_ms is spent, and
// at the first error or too-slow frame. bytes_per_frame and gc_ms are
// averaged / summed over the repetitions.
Repeated run_repeated(const std::string& path, const Scene& scene, RunConfig cfg, int reps);

// Whether a path runs Guile (and so gets a process of its own).
bool runs_guile(const std::string& path);

}  // namespace bench
