// SPDX-License-Identifier: MIT
// The figures of one speed run: the stdout table, JSON and the Org document.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "common/run_info.hpp"
#include "common/timing.hpp"
#include "speed/paths.hpp"

namespace bench {

struct Row {
    std::string scene;
    int n = 0;
    std::string path;
    std::string status = "ok";  // ok, skipped, error
    std::string reason;         // why skipped, or the error
    int warmup = 0, frames = 0;  // frames: timed, over all repetitions
    int reps = 0;
    Stats stats;
    double ns_per_entity = -1;
    double bytes_per_frame = -1;  // < 0: not measured on this path
    double gc_share = -1;         // collection time / timed time (< 0: n/a)
    double ratio_to_guile = -1;   // median / guile's median; < 0: no guile figure
    double setup_ms = 0;
    double checksum = 0;  // NaN: not computed
    int checksum_frames = 0;
    FrameSplit split;  // the guile path's: where its frames went
};

void print_header(std::FILE* out);
void print_row(std::FILE* out, const Row& row);
// The second table: where each guile row's frames went (rows with a split).
void print_splits(std::FILE* out, const std::vector<Row>& rows);

void write_json(const std::string& file, const RunInfo& info, const std::vector<Row>& rows);
// Writes the results between the "# BEGIN/END downstroke-bench results"
// markers of an existing file (keeping the rest), or a whole new document.
void write_org(const std::string& file, const RunInfo& info, const std::vector<Row>& rows);

}  // namespace bench
