// SPDX-License-Identifier: MIT
// downstroke-bench soak: every demo (demo/*.scm) run headless for many
// frames inside this process's Guile, with the memory it holds sampled
// after a warm-up and at the end (bench/scheme/bench/soak.scm does the
// running and sampling).
//
//   downstroke-bench soak [--frames N] [--warmup W] [--org FILE]
//
// N defaults to 10^6, W to 2000. --org writes the figures as an Org
// document (docs/soak.org).
#pragma once
#include "speed/options.hpp"

namespace bench {

int soak(const Options& opts);

}  // namespace bench
