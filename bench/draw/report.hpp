// SPDX-License-Identifier: MIT
// The figures of `downstroke-bench draw`: one row per case, the two goals,
// the stdout table and the "Drawing" section of docs/benchmarks.org.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "common/run_info.hpp"
#include "common/timing.hpp"

namespace bench::draw {

// The goal: a drawn frame's median at most this, on the 2-core machine.
constexpr double kGoalMs = 4.0;
// Map-size independence holds when the other sizes' fastest frames are
// within this share of the 1000 × 1000 map's. The fastest, not the median:
// other tenants of the VM moved one case's median by up to 27 % against an
// identical one in the same run while the minima agreed to 1 %, and a cost
// that grew with the map would be in every frame, the fastest included.
constexpr double kSizeTolerance = 0.10;

struct Row {
    std::string name;     // the case
    int map_side = 0;     // cells
    int size_case = 0;    // the map side of a map-size case, 0 otherwise
    std::string sprites;  // where the sprites are
    std::string camera;   // what the camera crosses
    bool debug = false;
    int frames = 0;       // timed, over all rounds
    Stats stats;
    double tiles = 0, drawn = 0;  // tiles and sprites drawn per frame, mean
    // Median and min over the 1000 × 1000 map-size case's (< 0: not a map-size case).
    double ratio = -1, min_ratio = -1;
};

struct Goal {
    std::string name, measured;
    bool met = false;
};
std::vector<Goal> judge(const std::vector<Row>& rows);

struct Document {
    RunInfo info;
    int warmup = 0, rounds = 0, frames = 0;  // frames: timed per case, over all rounds
    std::vector<Row> rows;
    std::vector<Goal> goals;
};

void print_rows(std::FILE* out, const std::vector<Row>& rows);
void print_goals(std::FILE* out, const std::vector<Goal>& goals);
// Writes the section between the "# BEGIN/END downstroke-bench drawing"
// markers of `file`, keeping the rest; appended at its end the first time.
void write_org(const std::string& file, const Document& doc);

}  // namespace bench::draw
