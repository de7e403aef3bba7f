// SPDX-License-Identifier: MIT
// downstroke-bench slopes: what ramps cost against the same scene on flat
// tiles, the two worlds stepped frame by frame in turn (slope_cost.cpp says
// why and what is measured).
#pragma once
namespace bench {
// argv[1] is "slopes".
int slopes_main(int argc, char** argv);
}  // namespace bench
