// SPDX-License-Identifier: MIT
#include "common/run_info.hpp"

#include <sys/utsname.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

namespace bench {

namespace {

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(line.find_first_not_of(" \t", colon + 1));
        }
    return "unknown";
}

int cpu_count() {
    std::ifstream in("/proc/cpuinfo");
    int n = 0;
    for (std::string line; std::getline(in, line);)
        if (line.rfind("processor", 0) == 0) ++n;
    return n ? n : static_cast<int>(std::thread::hardware_concurrency());
}

std::string shell_output(const std::string& command) {
    std::string out;
    if (std::FILE* p = popen(command.c_str(), "r")) {
        char buf[256];
        while (std::fgets(buf, sizeof buf, p)) out += buf;
        pclose(p);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

// The commit the core was built from, as far as the source tree tells.
std::string source_state() {
    const std::string git = "git -C '" DS_BENCH_SOURCE_DIR "' ";
    const std::string commit = shell_output(git + "rev-parse --short HEAD 2>/dev/null");
    if (commit.empty()) return "unknown (not a git checkout)";
    const std::string dirty = shell_output(git + "status --porcelain -- src bindings scheme 2>/dev/null");
    return "commit " + commit + (dirty.empty() ? "" : ", with uncommitted changes in src/ bindings/ scheme/");
}

}  // namespace

RunInfo collect_run_info(const std::string& command) {
    RunInfo info;
    info.command = command;
    info.cpu = cpu_model();
    info.cores = cpu_count();
    struct utsname u;
    if (uname(&u) == 0) info.kernel = u.release;
    char buf[64];
    const std::time_t t = std::time(nullptr);
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
    info.date = buf;
    info.build_type = DS_BENCH_BUILD_TYPE;
    info.core_flags = DS_BENCH_CORE_FLAGS;
    info.bench_flags = DS_BENCH_OWN_FLAGS;
    info.compiler = DS_BENCH_COMPILER;
    info.source = source_state();
    return info;
}

}  // namespace bench
