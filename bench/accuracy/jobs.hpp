// SPDX-License-Identifier: MIT
// Runs independent jobs on a few threads: the long accuracy runs share
// nothing but read-only scenes, and a 10^5-frame crowd is too slow to run
// one configuration after another.
#pragma once
#include <functional>
#include <vector>

namespace bench::accuracy {

// Runs every job once, at most `threads` at a time, in list order (put the
// longest first); returns when all are done. An exception in a job is
// rethrown here (the first one).
void run_jobs(const std::vector<std::function<void()>>& jobs, int threads);

}  // namespace bench::accuracy
