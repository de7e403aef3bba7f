// SPDX-License-Identifier: MIT
// What every bench mode records about the run beside its figures: the
// machine, the build, the source it was built from and the command line.
#pragma once
#include <string>

namespace bench {

struct RunInfo {
    std::string date, cpu, kernel, build_type, core_flags, bench_flags, compiler;
    std::string guile_version, box2d_version, box2d3_version, command;  // the versions: the speed mode only
    std::string source;  // commit, and whether src/ bindings/ scheme/ had uncommitted changes
    int cores = 0;
    double total_s = 0;
};

RunInfo collect_run_info(const std::string& command);

}  // namespace bench
