// SPDX-License-Identifier: MIT
// downstroke-bench accuracy: the work-precision benchmark. For collision
// mode × sub-frames k × resting contacts, how long a frame takes against
// how far the physics strays from a known truth (accuracy/measures.hpp,
// accuracy/runs.hpp).
//
//   downstroke-bench accuracy [--quick] [--org FILE] [--png FILE]
//
// Prints the table and the goals met or missed, writes the Org document
// (docs/accuracy.org) and, when gnuplot is installed, the plot
// (docs/accuracy.png). Exits 0 whether or not the goals are met.
#pragma once

namespace bench {

// argv[1] is "accuracy".
int accuracy_main(int argc, char** argv);

}  // namespace bench
