// SPDX-License-Identifier: MIT
// The Guile paths run each combination in a child process of their own
// (this executable, mode `child`), so every measurement starts from a fresh
// Guile heap: in one long-lived process the heap a 100000-entity run grew
// would make later, smaller runs collect far less often than they would
// on their own.
#pragma once
#include <string>

#include "speed/runs.hpp"

namespace bench {

// Runs run_repeated(path, make_scene(scene, n), cfg, reps) in a child.
Repeated run_in_child(const std::string& path, const std::string& scene, int n, const RunConfig& cfg,
                      int reps);

// The child's side: argv = {exe, "child", scene, n, path, warmup, frames,
// reps, max_frame_ms, budget_ms}. Prints the result as text on stdout.
int child_main(int argc, char** argv);

}  // namespace bench
