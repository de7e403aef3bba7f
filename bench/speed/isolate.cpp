// SPDX-License-Identifier: MIT
#include "speed/isolate.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "speed/scenes.hpp"

namespace bench {

namespace {

std::string self_exe() {
    char buf[4096];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) throw std::runtime_error("cannot find this executable (/proc/self/exe)");
    buf[n] = '\0';
    return buf;
}

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

// The result as "key value…" lines.
std::string encode(const Repeated& rep) {
    const PathResult& r = rep.result;
    std::ostringstream o;
    o.precision(17);
    o << "reps " << rep.reps << "\n";
    o << "frames";
    for (double ms : r.frame_ms) o << ' ' << ms;
    o << "\nbytes_per_frame " << r.bytes_per_frame << "\ngc_ms " << r.gc_ms << "\nsetup_ms " << r.setup_ms
      << "\nspent_ms " << r.spent_ms << "\n";
    const FrameSplit& s = r.split;
    if (s.frames > 0)
        o << "split " << s.frames << ' ' << s.decode_ms << ' ' << s.steps_ms << ' ' << s.encode_ms << ' '
          << s.collect_ms << ' ' << s.collections << ' ' << s.bytes << ' ' << s.rewritten << "\n";
    if (!std::isnan(r.checksum)) o << "checksum " << r.checksum << ' ' << r.checksum_frames << "\n";
    if (!r.skipped.empty()) o << "skipped " << one_line(r.skipped) << "\n";
    if (!r.error.empty()) o << "error " << one_line(r.error) << "\n";
    return o.str();
}

Repeated decode(const std::string& text) {
    Repeated rep;
    PathResult& r = rep.result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream l(line);
        std::string key;
        l >> key;
        std::string rest;
        std::getline(l >> std::ws, rest);
        std::istringstream v(rest);
        if (key == "reps") v >> rep.reps;
        else if (key == "frames")
            for (double ms; v >> ms;) r.frame_ms.push_back(ms);
        else if (key == "bytes_per_frame") v >> r.bytes_per_frame;
        else if (key == "gc_ms") v >> r.gc_ms;
        else if (key == "setup_ms") v >> r.setup_ms;
        else if (key == "spent_ms") v >> r.spent_ms;
        else if (key == "split") {
            FrameSplit& s = r.split;
            v >> s.frames >> s.decode_ms >> s.steps_ms >> s.encode_ms >> s.collect_ms >> s.collections >> s.bytes >>
                s.rewritten;
        } else if (key == "checksum") v >> r.checksum >> r.checksum_frames;
        else if (key == "skipped") r.skipped = rest;
        else if (key == "error") r.error = rest;
    }
    return rep;
}

}  // namespace

Repeated run_in_child(const std::string& path, const std::string& scene, int n, const RunConfig& cfg,
                      int reps) {
    std::ostringstream cmd;
    cmd.precision(17);
    cmd << '\'' << self_exe() << "' child " << scene << ' ' << n << ' ' << path << ' ' << cfg.warmup << ' '
        << cfg.frames << ' ' << reps << ' ' << cfg.max_frame_ms << ' ' << std::min(cfg.budget_ms, 1e15);
    std::fflush(stdout);
    std::FILE* p = popen(cmd.str().c_str(), "r");
    if (!p) throw std::runtime_error("cannot start " + cmd.str());
    std::string out;
    char buf[65536];
    for (size_t got; (got = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, got);
    const int status = pclose(p);
    Repeated rep = decode(out);
    if (status != 0 && rep.result.error.empty())
        rep.result.error = "child process failed (status " + std::to_string(status) + ")";
    return rep;
}

int child_main(int argc, char** argv) {
    if (argc != 10) {
        std::fprintf(stderr, "downstroke-bench child: expected 8 arguments\n");
        return 2;
    }
    Repeated rep;
    try {
        const Scene scene = make_scene(argv[2], std::atoi(argv[3]));
        RunConfig cfg{std::atoi(argv[5]), std::atoi(argv[6]), std::atof(argv[8]), std::atof(argv[9])};
        rep = run_repeated(argv[4], scene, cfg, std::atoi(argv[7]));
    } catch (const std::exception& e) {
        rep.result.error = e.what();
    }
    const std::string text = encode(rep);
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
}

}  // namespace bench
