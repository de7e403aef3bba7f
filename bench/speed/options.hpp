// SPDX-License-Identifier: MIT
// The command line of downstroke-bench: the speed mode's options, which
// the soak mode shares (mode, --frames, --warmup, --org), and the usage of
// every mode. The other modes parse their own (common/command_line.hpp).
#pragma once
#include <string>
#include <vector>

namespace bench {

struct Options {
    std::string mode = "speed";        // the first positional argument
    std::vector<std::string> scenes;   // --scene (default: all)
    std::vector<int> ns;               // --n (default: 100 1000 10000 100000)
    std::vector<std::string> paths;    // --path (default: all)
    int frames = 0;                    // --frames (0: default_frames)
    int warmup = -1;                   // --warmup (-1: default_warmup)
    int reps = 0;                      // --reps (0: default_reps by N)
    double max_frame_s = 2.0;          // --max-frame-s: skip above this estimate
    double budget_s = 6.0;             // --budget: timed seconds per combination
    std::string json, org;             // --json FILE, --org FILE
    std::string command;               // the command line as given
    bool help = false;
};

const std::vector<std::string>& path_names();
// Parses argv; throws std::invalid_argument with a message on a bad option.
Options parse_options(int argc, char** argv);
std::string usage();

// One repetition builds the world afresh, runs the warm-up frames, then
// times the frames: the same window of the scene's motion at every N. Small
// N repeat it to gather enough frames.
int default_frames();
int default_warmup();
int default_reps(int n);

}  // namespace bench
