// SPDX-License-Identifier: MIT
// downstroke-bench [speed], the default mode: how long one physics frame
// takes, per scene × N × path (speed/scenes.hpp, speed/paths.hpp). Each
// combination is repeated from fresh worlds under a time budget (speed/runs.hpp),
// the Guile paths in a child process each (speed/isolate.hpp); combinations
// estimated to be too slow are skipped. Prints a table, and with --json or
// --org writes the figures (speed/report.hpp).
#pragma once
#include "speed/options.hpp"

namespace bench {

// Exits non-zero when a combination failed.
int speed(const Options& opts);

}  // namespace bench
