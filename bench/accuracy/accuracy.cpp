// SPDX-License-Identifier: MIT
#include "accuracy/accuracy.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include "accuracy/format.hpp"
#include "accuracy/jobs.hpp"
#include "accuracy/plot.hpp"
#include "accuracy/report.hpp"
#include "common/command_line.hpp"
#include "common/timing.hpp"

namespace bench::accuracy {

namespace {

struct Args {
    bool quick = false, help = false, every_frame = false;
    int jobs = 0;  // 0: one per core
    std::string org = DS_BENCH_SOURCE_DIR "/docs/accuracy.org";
    std::string png = DS_BENCH_SOURCE_DIR "/docs/accuracy.png";
    std::string command;
};

const char* kUsage =
    "usage: downstroke-bench accuracy [--quick] [--org FILE] [--png FILE]\n"
    "  --quick      10^3 frames of the resting scenes instead of 10^5, 100 of the others\n"
    "  --org FILE   the Org document (default: docs/accuracy.org)\n"
    "  --png FILE   the plot (default: docs/accuracy.png; needs gnuplot)\n"
    "  --every-frame  step every frame of the long runs, even once their state cycles\n"
    "  --jobs N     threads for the untimed runs (default: one per core)\n";

Args parse(int argc, char** argv) {
    Args a;
    a.command = command_line(argc, argv);
    for (int i = 2; i < argc; ++i) {
        const std::string opt = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(opt + ": missing value");
            return argv[++i];
        };
        if (opt == "--quick") a.quick = true;
        else if (opt == "--org") a.org = value();
        else if (opt == "--png") a.png = value();
        else if (opt == "--every-frame") a.every_frame = true;
        else if (opt == "--jobs") a.jobs = count_arg(opt, value(), 1);
        else if (opt == "--help" || opt == "-h") a.help = true;
        else throw std::invalid_argument("accuracy: unknown argument " + opt);
    }
    return a;
}

Plan plan_for(const Args& a) {
    Plan p;
    p.quick = a.quick;
    if (a.quick) {
        p.scene_frames = 100;
        p.drift_frames = 1000;
        p.sinking_frames = 100;
    }
    p.shortcut = !a.every_frame;
    p.jobs = a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return p;
}

std::vector<Config> configs() {
    std::vector<Config> cs;
    for (ds::CollisionMode mode : {ds::CollisionMode::Discrete, ds::CollisionMode::Swept})
        for (bool resting : {false, true})
            for (int k : {1, 2, 4, 8}) cs.push_back({mode, k, resting});
    return cs;
}

// The timed part, one configuration after another so nothing else runs
// beside the clock: the arena, with the cheap trajectory and tunneling.
void measure_timed(std::vector<Row>& rows, const Plan& p) {
    for (Row& r : rows) {
        const int64_t t0 = now_ns();
        r.traj = measure_trajectory(r.cfg, p.traj_frames);
        r.tunnel = measure_tunneling(r.cfg, p.max_speed);
        r.ramp_tunnel = measure_ramp_tunneling(r.cfg, p.max_speed);
        r.arena = run_scene(arena(p.arena_n), r.cfg, p.scene_frames, p.shortcut);
        std::fprintf(stderr, "accuracy: timed %s, %.1f s\n", config_name(r.cfg).c_str(),
                     static_cast<double>(now_ns() - t0) / 1e9);
    }
}

// The long runs, in parallel, the slowest (most sub-frames) first.
void measure_untimed(std::vector<Row>& rows, std::vector<Sinking>& sinking, const Plan& p) {
    const Setup drop_scene = drop(), stack_scene = stack(p.stack_n), crowd_scene = resting_crowd(p.crowd_n);
    std::vector<std::function<void()>> jobs;
    auto add = [&](Run& out, const Setup& s, long frames, const Config& c) {
        jobs.push_back([&out, &s, frames, c, &p] {
            const int64_t t0 = now_ns();
            out = run_scene(s, c, frames, p.shortcut);
            std::fprintf(stderr, "accuracy: %s %s: %ld of %ld frames stepped, %.1f s\n", s.name.c_str(),
                         config_name(c).c_str(), out.stepped, out.frames, static_cast<double>(now_ns() - t0) / 1e9);
        });
    };
    for (int k : {8, 4, 2, 1})
        for (Row& r : rows)
            if (r.cfg.k == k) {
                add(r.crowd, crowd_scene, p.drift_frames, r.cfg);
                add(r.stack, stack_scene, p.drift_frames, r.cfg);
                add(r.drop, drop_scene, p.scene_frames, r.cfg);
            }
    // The check, under each push rule, the largest first.
    for (const std::string& scene : sinking_scenes())
        for (int n : sinking_ns(p.quick))
            for (ds::PushRule rule : {ds::PushRule::Clipped, ds::PushRule::Seed}) sinking.push_back({scene, n, rule});
    for (size_t i = sinking.size(); i-- > 0;)
        jobs.push_back([&out = sinking[i], &p] {
            const int64_t t0 = now_ns();
            out = measure_sinking(out.scene, out.n, out.rule, p.sinking_frames);
            std::fprintf(stderr, "accuracy: sinking %s %d %s: %ld of %ld bodies sunk, %.1f s\n", out.scene.c_str(),
                         out.n, out.rule == ds::PushRule::Seed ? "seed" : "clipped", out.sunk, out.movers,
                         static_cast<double>(now_ns() - t0) / 1e9);
        });
    run_jobs(jobs, p.jobs);
}

std::vector<Row> measure_all(const Plan& p, std::vector<Sinking>& sinking) {
    std::vector<Row> rows;
    for (const Config& c : configs()) {
        rows.emplace_back();
        rows.back().cfg = c;
    }
    measure_timed(rows, p);
    measure_untimed(rows, sinking, p);
    for (size_t i = 1; i < rows.size(); ++i)
        if (rows[i].cfg.k > 1) rows[i].ratio = rows[i - 1].traj.max_error / rows[i].traj.max_error;
    print_header(stdout);
    for (const Row& r : rows) print_row(stdout, r);
    return rows;
}

std::string relative_link(const std::string& png, const std::string& org) {
    namespace fs = std::filesystem;
    const fs::path from = fs::absolute(org).parent_path();
    return fs::absolute(png).lexically_relative(from).string();
}

}  // namespace

}  // namespace bench::accuracy

namespace bench {

int accuracy_main(int argc, char** argv) {
    using namespace accuracy;
    const Args args = parse(argc, argv);
    if (args.help) {
        std::fputs(kUsage, stdout);
        return EXIT_SUCCESS;
    }
    const int64_t t0 = now_ns();
    Document doc;
    doc.plan = plan_for(args);
    doc.rows = measure_all(doc.plan, doc.sinking);
    doc.goals = judge(doc.rows, doc.sinking);
    print_goals(stdout, doc.goals);
    const PlotResult plot = write_plot(args.png, doc.rows);
    std::printf("plot: %s\n", plot.note.c_str());
    if (plot.written) doc.png_link = relative_link(args.png, args.org);
    doc.plot_note = plot.note;
    doc.info = collect_run_info(args.command);
    doc.info.total_s = static_cast<double>(now_ns() - t0) / 1e9;
    write_org(args.org, doc);
    std::printf("whole run: %.1f s; wrote %s\n", doc.info.total_s, args.org.c_str());
    return EXIT_SUCCESS;
}

}  // namespace bench
