// SPDX-License-Identifier: MIT
#include "speed/runs.hpp"

#include <algorithm>
#include <stdexcept>

namespace bench {

bool runs_guile(const std::string& path) { return path == "guile" || path == "reference"; }

PathResult run_path(const std::string& path, const Scene& scene, const RunConfig& cfg) {
    if (path == "native") return run_native(scene, cfg);
    if (path == "bare") return run_bare(scene, cfg);
    if (path == "guile") return run_guile(scene, cfg, false);
    if (path == "reference") return run_guile(scene, cfg, true);
#if DS_BENCH_HAVE_BOX2D
    if (path == "box2d") return run_box2d(scene, cfg, false);
    if (path == "box2d-discrete") return run_box2d(scene, cfg, true);
#endif
#if DS_BENCH_HAVE_BOX2D3
    if (path == "box2d3") return run_box2d3(scene, cfg, 1);
    if (path == "box2d3-2") return run_box2d3(scene, cfg, 2);
#endif
    throw std::logic_error("no path " + path);
}

Repeated run_repeated(const std::string& path, const Scene& scene, RunConfig cfg, int reps) {
    const double budget_ms = cfg.budget_ms;
    Repeated out;
    PathResult& r = out.result;
    double spent = 0;
    for (int k = 0; k < reps; ++k) {
        if (k > 0 && spent > budget_ms) break;
        cfg.budget_ms = std::max(budget_ms - spent, 0.0);
        PathResult one = run_path(path, scene, cfg);
        one.checksum_frames = cfg.warmup + static_cast<int>(one.frame_ms.size());
        spent += one.spent_ms;
        ++out.reps;
        const bool stop = !one.error.empty() || !one.skipped.empty();
        if (k == 0 || stop) {
            r = std::move(one);
            if (stop) break;
            continue;
        }
        r.frame_ms.insert(r.frame_ms.end(), one.frame_ms.begin(), one.frame_ms.end());
        if (r.bytes_per_frame >= 0) r.bytes_per_frame += one.bytes_per_frame;
        if (r.gc_ms >= 0) r.gc_ms += one.gc_ms;
        r.split.add(one.split);
        r.checksum = one.checksum;
        r.checksum_frames = one.checksum_frames;
    }
    if (r.bytes_per_frame >= 0 && out.reps > 0) r.bytes_per_frame /= out.reps;
    r.spent_ms = spent;
    return out;
}

}  // namespace bench
