// SPDX-License-Identifier: MIT
#include "speed/options.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "common/command_line.hpp"
#include "speed/scenes.hpp"

namespace bench {

namespace {

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

}  // namespace

const std::vector<std::string>& path_names() {
    static const std::vector<std::string> names = {"guile", "native", "bare", "reference", "box2d",
                                                   "box2d-discrete", "box2d3", "box2d3-2"};
    return names;
}

int default_frames() { return 30; }
int default_warmup() { return 10; }
int default_reps(int n) { return n <= 100 ? 10 : n <= 1000 ? 4 : n <= 10000 ? 2 : 1; }

std::string usage() {
    return "usage: downstroke-bench [speed] [options]   how long a frame takes\n"
           "       downstroke-bench soak [--frames N] [--org FILE]   memory of each demo over N frames\n"
           "       downstroke-bench accuracy [--quick] [--org FILE] [--png FILE]   run time against error\n"
           "       downstroke-bench draw [--frames F] [--warmup W] [--rounds R] [--org FILE]   one drawn frame\n"
           "       downstroke-bench query [--frames F] [--org FILE]   spatial queries per frame\n"
           "       downstroke-bench tile-edit [--rounds R] [--org FILE]   one tile edit\n"
           "       downstroke-bench slopes [--n N[,N…]] [--rounds R] [--frames F] [--org FILE]   ramps against flat tiles, in turn\n"
           "speed options:\n"
           "  --scene S[,S…]   rain crowd rest bullets platformer ramps ramps-flat\n"
           "                   crowd-categories crowd-sensors crowd-resting crowd-visitor\n"
           "                   shots shots-quiet shots-author-first shots-author-first-quiet\n"
           "                   knobs knobs-off (default: all)\n"
           "  --n N[,N…]       entity counts (default: 100,1000,10000,100000)\n"
           "  --path P[,P…]    guile native bare reference box2d box2d-discrete box2d3 box2d3-2\n"
           "                   (default: all; native also runs bare)\n"
           "  --frames F       timed frames per repetition (30)\n"
           "  --warmup W       untimed frames before them (10)\n"
           "  --reps R         repetitions, each from a fresh world (by N: 10/4/2/1)\n"
           "  --max-frame-s S  skip a combination whose frame is estimated, or turns out,\n"
           "                   to take more than S s (2)\n"
           "  --budget S       stop repeating, then stop timing, once one combination\n"
           "                   has spent about S s stepping (never below 3 frames) (6)\n"
           "  --json FILE      write the figures as JSON\n"
           "  --org FILE       write them as an Org document (docs/benchmarks.org)\n";
}

Options parse_options(int argc, char** argv) {
    Options o;
    o.command = command_line(argc, argv);
    bool positional_seen = false;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        std::string value;
        const bool takes_value = a == "--scene" || a == "--n" || a == "--path" || a == "--frames" ||
                                 a == "--warmup" || a == "--reps" || a == "--json" || a == "--org" ||
                                 a == "--max-frame-s" || a == "--budget";
        if (const auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = a.substr(eq + 1);
            a = a.substr(0, eq);
        } else if (takes_value) {
            if (i + 1 >= argc) throw std::invalid_argument(a + ": missing value");
            value = argv[++i];
        }
        if (a == "--help" || a == "-h") o.help = true;
        else if (a == "--scene")
            for (auto& s : split(value)) {
                if (!is_scene(s)) throw std::invalid_argument("--scene: unknown scene '" + s + "'");
                o.scenes.push_back(s);
            }
        else if (a == "--n")
            for (auto& s : split(value)) {
                const int n = count_arg(a, s, 0);
                if (n == 0) throw std::invalid_argument("--n: N must be at least 1");
                o.ns.push_back(n);
            }
        else if (a == "--path")
            for (auto& s : split(value)) {
                if (std::find(path_names().begin(), path_names().end(), s) == path_names().end())
                    throw std::invalid_argument("--path: unknown path '" + s + "'");
                o.paths.push_back(s);
            }
        else if (a == "--frames") {
            o.frames = count_arg(a, value, 0);
            if (o.frames == 0) throw std::invalid_argument("--frames: at least 1");
        } else if (a == "--warmup") o.warmup = count_arg(a, value, 0);
        else if (a == "--reps") {
            o.reps = count_arg(a, value, 0);
            if (o.reps == 0) throw std::invalid_argument("--reps: at least 1");
        }
        else if (a == "--json") o.json = value;
        else if (a == "--org") o.org = value;
        else if (a == "--max-frame-s") o.max_frame_s = positive_arg(a, value);
        else if (a == "--budget") o.budget_s = positive_arg(a, value);
        else if (a.rfind("-", 0) == 0) throw std::invalid_argument("unknown option " + a);
        else if (!positional_seen) {
            o.mode = a;
            positional_seen = true;
        } else throw std::invalid_argument("unexpected argument " + a);
    }
    if (o.scenes.empty()) o.scenes = scene_names();
    if (o.ns.empty()) o.ns = {100, 1000, 10000, 100000};
    std::sort(o.ns.begin(), o.ns.end());
    o.ns.erase(std::unique(o.ns.begin(), o.ns.end()), o.ns.end());
    if (o.paths.empty()) o.paths = path_names();
    if (std::find(o.paths.begin(), o.paths.end(), "native") != o.paths.end() &&
        std::find(o.paths.begin(), o.paths.end(), "bare") == o.paths.end())
        o.paths.push_back("bare");
    // Run in the canonical order: guile first, so the others' ratios exist.
    std::vector<std::string> ordered;
    for (const auto& p : path_names())
        if (std::find(o.paths.begin(), o.paths.end(), p) != o.paths.end()) ordered.push_back(p);
    o.paths = ordered;
    return o;
}

}  // namespace bench
