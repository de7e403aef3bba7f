// SPDX-License-Identifier: MIT
// downstroke-bench slopes: the cost of ramps (semantics §12), as the ramps
// scene against ramps-flat (speed/scenes.cpp), natively.
//
// The speed mode times one scene after the other. On a VM whose speed
// swings by a third or more for seconds at a time, the two can run on what
// is in effect two machines, and their ratio moves with the swing. Here
// both worlds are built side by side and stepped in turn, one frame of
// ramps then one of ramps-flat, so a swing slows both alike: a round is
// `warmup` untimed frames of each, then `frames` timed ones, and its ratio
// is Σ ramps ÷ Σ ramps-flat. Reported per N: the median round's ratio and
// the range, mean ms per frame, and the three steps the shapes touch, from
// ds::Frame's own step timers. Writes the "Slopes" section of
// docs/benchmarks.org.
//
//   downstroke-bench slopes [--n N[,N…]] [--rounds R] [--frames F] [--org FILE]
#include "slopes/slope_cost.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "common/org_file.hpp"
#include "common/run_info.hpp"
#include "common/timing.hpp"
#include "frame.hpp"
#include "speed/paths.hpp"
#include "speed/scenes.hpp"

namespace bench {

namespace {

const char* const kBegin = "# BEGIN downstroke-bench slopes";
const char* const kEnd = "# END downstroke-bench slopes";

// Frames before timing: the rain scene's boxes have all landed by about
// frame 25 and walk from then on (speed/scenes.cpp).
constexpr int kWarmup = 30;
// The steps whose cost a shape changes.
constexpr ds::StepId kShapeSteps[] = {ds::kStepTileX, ds::kStepTileY, ds::kStepOnSolid};

struct Options {
    std::vector<int> ns = {1000, 10000, 100000};
    int rounds = 9, frames = 60;
    std::string org = "docs/benchmarks.org";
};

std::vector<int> count_list(const std::string& opt, const std::string& v) {
    std::vector<int> out;
    std::stringstream in(v);
    for (std::string part; std::getline(in, part, ',');) out.push_back(count_arg(opt, part, 1));
    if (out.empty()) throw std::invalid_argument(opt + ": expected counts, got '" + v + "'");
    return out;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument(a + ": needs a value (or is no option of slopes)");
        const std::string v = argv[++i];
        if (a == "--n") o.ns = count_list(a, v);
        else if (a == "--rounds") o.rounds = count_arg(a, v, 1);
        else if (a == "--frames") o.frames = count_arg(a, v, 1);
        else if (a == "--org") o.org = v;
        else throw std::invalid_argument("slopes: unknown option " + a);
    }
    return o;
}

// One scene as the native path steps it.
struct Stepped {
    ds::TileGrid grid;
    ds::World world;
    ds::Frame frame;
    double ms = 0;                       // timed frames, summed
    double step_ms[ds::kStepCount] = {};  // the same, by step

    Stepped(const std::string& name, int n) {
        const Scene s = make_scene(name, n);
        grid = ds::TileGrid(s.cols, s.rows, s.tile, s.tile, s.solid);
        add_shapes(grid, s);
        world.grid = &grid;
        world.bodies = to_bodies(s);
    }
    Stepped(const Stepped&) = delete;  // world.grid points at grid

    void step(bool timed) {
        const int64_t t0 = now_ns();
        frame.step(world, ds::FrameOptions{});
        if (!timed) return;
        ms += static_cast<double>(now_ns() - t0) / 1e6;
        for (int k = 0; k < ds::kStepCount; ++k) step_ms[k] += frame.stats().step[k].ms;
    }
};

struct Round {
    double ratio, ramps_ms, flat_ms;  // per frame
    double ramps_step[ds::kStepCount], flat_step[ds::kStepCount];
};

Round run_round(int n, int frames) {
    Stepped ramps("ramps", n), flat("ramps-flat", n);
    for (int i = 0; i < kWarmup + frames; ++i) {
        ramps.step(i >= kWarmup);
        flat.step(i >= kWarmup);
    }
    Round r{ramps.ms / flat.ms, ramps.ms / frames, flat.ms / frames, {}, {}};
    for (int k = 0; k < ds::kStepCount; ++k) {
        r.ramps_step[k] = ramps.step_ms[k] / frames;
        r.flat_step[k] = flat.step_ms[k] / frames;
    }
    return r;
}

std::string row(int n, std::vector<Round> rounds) {
    std::sort(rounds.begin(), rounds.end(), [](const Round& a, const Round& b) { return a.ratio < b.ratio; });
    const Round& mid = rounds[rounds.size() / 2];
    std::ostringstream o;
    o << "| " << n << " | " << sig3(mid.ratio) << " | " << sig3(rounds.front().ratio) << "–"
      << sig3(rounds.back().ratio) << " | " << sig3(mid.ramps_ms) << " | " << sig3(mid.flat_ms);
    for (const ds::StepId id : kShapeSteps) o << " | " << sig3(mid.ramps_step[id]) << " / " << sig3(mid.flat_step[id]);
    o << " |\n";
    return o.str();
}

}  // namespace

int slopes_main(int argc, char** argv) {
    const Options opts = parse(argc, argv);
    const std::string command = command_line(argc, argv);
    const int64_t start = now_ns();
    std::string rows;
    for (const int n : opts.ns) {
        std::vector<Round> rounds;
        for (int r = 0; r < opts.rounds; ++r) rounds.push_back(run_round(n, opts.frames));
        const std::string line = row(n, rounds);
        std::fputs(line.c_str(), stderr);  // progress: a large N takes a while
        rows += line;
    }
    RunInfo info = collect_run_info(command);
    info.total_s = static_cast<double>(now_ns() - start) / 1e9;

    std::ostringstream o;
    o << kBegin << " (generated by downstroke-bench slopes; edits here are overwritten)\n* Slopes\n\n"
      << "What ramps cost (semantics §12): the ramps scene against ramps-flat, the same\n"
         "rain over the same map with every ramp cell empty (=bench/speed/scenes.cpp=),\n"
         "native, stepped in turn frame by frame in one process so that the VM's swings\n"
         "slow both alike (=bench/slopes/=).\n\n"
         "Measured by =" << info.command << "=\non "
      << info.cpu << ", " << info.cores << " cores, " << info.date << ", " << info.build_type << ", source "
      << info.source << ".\nEach of " << opts.rounds << " rounds per N builds both worlds, steps " << kWarmup
      << " untimed frames of each, then " << opts.frames
      << " timed ones;\nits ratio is Σ ramps ÷ Σ ramps-flat. The figures are the median round's; the\n"
         "steps are ms per frame, ramps / ramps-flat, from =ds::Frame='s step timers.\n\n"
      << "| N | ramps ÷ ramps-flat | range | ramps ms | ramps-flat ms "
         "| tile-collisions-x | tile-collisions-y | on-solid |\n|-\n"
      << rows << "\nWhole run: " << sig3(info.total_s) << " s.\n"
      << kEnd << "\n";
    std::fputs(o.str().c_str(), stdout);
    write_generated(opts.org, kBegin, kEnd, o.str(), "#+title: Benchmarks\n\n");
    return 0;
}

}  // namespace bench
