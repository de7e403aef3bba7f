// SPDX-License-Identifier: MIT
#include "speed/speed.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>

#include "common/guile_boot.hpp"
#include "common/timing.hpp"
#include "speed/isolate.hpp"
#include "speed/options.hpp"
#include "speed/paths.hpp"
#include "speed/report.hpp"
#include "speed/runs.hpp"
#include "speed/scenes.hpp"

namespace bench {

namespace {

struct Runner {
    explicit Runner(const Options& o) : opts(o) {}
    const Options& opts;
    Estimator est;

    // Guile paths in a child process each (speed/isolate.hpp), the rest in this one.
    Repeated run(const std::string& path, const std::string& scene_name, int n, const Scene* scene,
                 const RunConfig& cfg, int reps) {
        if (runs_guile(path)) return run_in_child(path, scene_name, n, cfg, reps);
        if (scene) return run_repeated(path, *scene, cfg, reps);
        return run_repeated(path, make_scene(scene_name, n), cfg, reps);
    }

    static std::string series(const std::string& scene, const std::string& path) { return scene + "/" + path; }

    double max_frame_ms() const { return opts.max_frame_s * 1000; }

    // Why a combination is not run, or "" to run it.
    std::string skip_reason(const std::string& scene, int n, const std::string& path) {
#if !DS_BENCH_HAVE_BOX2D
        if (path == "box2d" || path == "box2d-discrete") return "built without Box2D";
#endif
#if !DS_BENCH_HAVE_BOX2D3
        if (path.rfind("box2d3", 0) == 0) return "built without Box2D v3 (DOWNSTROKE_BENCH_BOX2D3_ROOT)";
#endif
        if (path.rfind("box2d", 0) == 0 && scene == "ramps")
            return "the Box2D path builds its tiles as boxes, without ramps";
        if (path.rfind("box2d", 0) == 0 && scene.rfind("shots", 0) == 0)
            return "the shots scenes measure the Scheme boundary's contact report, which Box2D has not";
        const double e = est.estimate(series(scene, path), n);
        if (e > max_frame_ms()) {
            char buf[128];
            std::snprintf(buf, sizeof buf, "estimated %.3g s/frame > %.3g s", e / 1000, opts.max_frame_s);
            return buf;
        }
        if (skipped_.count(series(scene, path)) && skipped_[series(scene, path)] <= n)
            return "a smaller N was already too slow";
        return "";
    }

    void remember_too_slow(const std::string& scene, int n, const std::string& path) {
        auto [it, fresh] = skipped_.emplace(series(scene, path), n);
        if (!fresh && n < it->second) it->second = n;
    }

    // With nothing measured below n for this series, short pilot runs at
    // the smaller standard sizes give the estimate something to go on.
    void pilot(const std::string& scene, int n, const std::string& path) {
        for (int p : {100, 1000, 10000}) {
            if (p >= n) break;
            const std::string s = series(scene, path);
            if (est.has(s, p)) continue;
            if (!skip_reason(scene, p, path).empty()) return;  // larger n: skipped too
            const PathResult r = run(path, scene, p, nullptr, {2, 3, max_frame_ms(), opts.budget_s * 1000}, 1).result;
            if (!r.skipped.empty()) {
                remember_too_slow(scene, p, path);
                return;
            }
            if (!r.error.empty() || r.frame_ms.empty()) return;
            est.record(s, p, summarize(r.frame_ms).mean_ms);
        }
    }

    Row measure(const Scene& scene, const std::string& path) {
        Row row;
        row.scene = scene.name;
        row.n = scene.n;
        row.path = path;
        if (path != "bare") pilot(scene.name, scene.n, path);
        row.reason = skip_reason(scene.name, scene.n, path);
        if (!row.reason.empty()) {
            row.status = "skipped";
            return row;
        }
        const double budget_ms = opts.budget_s * 1000;
        RunConfig cfg{opts.warmup >= 0 ? opts.warmup : default_warmup(),
                      opts.frames > 0 ? opts.frames : default_frames(), max_frame_ms(), budget_ms};
        int reps = opts.reps > 0 ? opts.reps : default_reps(scene.n);
        const double e = est.estimate(series(scene.name, path), scene.n);
        if (e > 0 && opts.reps == 0)  // fewer repetitions to keep to the budget
            reps = std::max(1, std::min(reps, static_cast<int>(budget_ms / (e * (cfg.warmup + cfg.frames)))));
        const Repeated rep = run(path, scene.name, scene.n, &scene, cfg, reps);
        const PathResult& r = rep.result;
        if (!r.error.empty()) {
            row.status = "error";
            row.reason = r.error;
            return row;
        }
        if (!r.skipped.empty()) {
            row.status = "skipped";
            row.reason = r.skipped;
            remember_too_slow(scene.name, scene.n, path);
            return row;
        }
        row.reps = rep.reps;
        row.warmup = cfg.warmup;
        row.frames = static_cast<int>(r.frame_ms.size());
        row.stats = summarize(r.frame_ms);
        row.ns_per_entity = row.stats.median_ms * 1e6 / scene.n;
        row.bytes_per_frame = r.bytes_per_frame;
        if (r.gc_ms >= 0) {
            double timed = 0;
            for (double ms : r.frame_ms) timed += ms;
            row.gc_share = timed > 0 ? r.gc_ms / timed : 0;
        }
        row.setup_ms = r.setup_ms;
        row.checksum = r.checksum;
        row.checksum_frames = r.checksum_frames;
        row.split = r.split;
        // The mean, not the median: it carries the garbage collections.
        est.record(series(scene.name, path), scene.n, row.stats.mean_ms);
        return row;
    }

private:
    std::map<std::string, int> skipped_;  // series → smallest N found too slow
};

bool uses_guile(const Options& o) {
    for (const auto& p : o.paths)
        if (p == "guile" || p == "reference") return true;
    return false;
}

}  // namespace

int speed(const Options& opts) {
    const int64_t t_start = now_ns();
    RunInfo info = collect_run_info(opts.command);
    info.guile_version = uses_guile(opts) ? guile_version() : "not used";  // boots Guile; not used for timing
#if DS_BENCH_HAVE_BOX2D
    info.box2d_version = box2d_version();
#endif
#if DS_BENCH_HAVE_BOX2D3
    info.box2d3_version = box2d3_version();
#endif
    std::vector<Row> rows;
    Runner runner(opts);
    print_header(stdout);
    for (const auto& name : opts.scenes)
        for (int n : opts.ns) {
            std::unique_ptr<Scene> scene;
            std::string scene_error;
            try {
                scene = std::make_unique<Scene>(make_scene(name, n));
            } catch (const std::exception& e) {
                scene_error = e.what();
            }
            double guile_median = -1;
            for (const auto& path : opts.paths) {
                Row row;
                if (!scene) {
                    row.scene = name;
                    row.n = n;
                    row.path = path;
                    row.status = "error";
                    row.reason = scene_error;
                } else {
                    row = runner.measure(*scene, path);
                }
                if (row.status == "ok" && path == "guile") guile_median = row.stats.median_ms;
                if (row.status == "ok" && guile_median > 0) row.ratio_to_guile = row.stats.median_ms / guile_median;
                print_row(stdout, row);
                rows.push_back(row);
            }
        }
    print_splits(stdout, rows);
    info.total_s = static_cast<double>(now_ns() - t_start) / 1e9;
    std::printf("whole run: %.1f s\n", info.total_s);
    if (!opts.json.empty()) write_json(opts.json, info, rows);
    if (!opts.org.empty()) write_org(opts.org, info, rows);
    for (const Row& r : rows)
        if (r.status == "error") return EXIT_FAILURE;
    return EXIT_SUCCESS;
}

}  // namespace bench
