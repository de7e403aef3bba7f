// SPDX-License-Identifier: MIT
// The figures of `downstroke-bench accuracy`: one row per Config, the goals
// they meet or miss, the stdout table and the Org document.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "accuracy/runs.hpp"
#include "accuracy/sinking.hpp"
#include "common/run_info.hpp"

namespace bench::accuracy {

// How much of each scene a run covers.
struct Plan {
    bool quick = false;
    int traj_frames = 60;
    int max_speed = 500;
    long scene_frames = 300;     // arena and drop
    long drift_frames = 100000;  // stack and crowd
    int arena_n = 512;
    int stack_n = 20;
    int crowd_n = 256;  // 32 stacks and a pillar; larger and the full run passes 2 min on 2 cores
    bool shortcut = true;  // stop a run early once its whole state cycles (run_scene)
    int jobs = 2;          // threads for the runs after the timed ones
    long sinking_frames = 300;  // the check (Sinking), as the issue counted it
};

struct Row {
    Config cfg;
    Trajectory traj;
    double ratio = 0;  // the trajectory error at k/2 over the one at k (0 for k = 1)
    Tunneling tunnel;
    Tunneling ramp_tunnel;  // against ramps
    Run arena, drop, stack, crowd;

    // The scene run with the deepest penetration (the first on a tie).
    const Run& deepest() const;
};

struct Goal {
    std::string name;
    bool met = false;
    std::string detail;
};
std::vector<Goal> judge(const std::vector<Row>& rows, const std::vector<Sinking>& sinking);

void print_header(std::FILE* out);
void print_row(std::FILE* out, const Row& row);
void print_goals(std::FILE* out, const std::vector<Goal>& goals);

struct Document {
    RunInfo info;
    Plan plan;
    std::vector<Row> rows;
    std::vector<Sinking> sinking;  // per scene and N, the default rule then the seed's
    std::vector<Goal> goals;
    std::string png_link;  // the plot, relative to the document ("" when skipped)
    std::string plot_note;  // what became of the plot
};
// Writes the figures between the "# BEGIN/END downstroke-bench accuracy"
// markers of an existing file (the rest is kept), or a whole new document.
void write_org(const std::string& file, const Document& doc);

}  // namespace bench::accuracy
