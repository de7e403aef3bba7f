// SPDX-License-Identifier: MIT
// The paths a scene is stepped through. Each builds its own world from the
// Scene, runs `warmup` untimed frames, then up to `frames` timed frames,
// under a FrameGuard (common/timing.hpp) built from the config.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "body.hpp"
#include "frame.hpp"
#include "speed/scenes.hpp"
#include "tile_grid.hpp"

namespace bench {

struct RunConfig {
    int warmup = 0;
    int frames = 0;
    double max_frame_ms = 2000;  // any frame slower than this: stop, skipped
    double budget_ms = 1e300;    // stop timing once the frames add up to this (≥ 3 timed)
};

// Where the guile path's timed frames went, summed over them, from the rows
// of engine-stats (%frame-stats): the boundary, the steps and the collector
// apart. Per frame: divide by `frames`.
struct FrameSplit {
    int frames = 0;  // 0: not measured on this path
    double decode_ms = 0, steps_ms = 0, encode_ms = 0, collect_ms = 0;
    double collections = 0, bytes = 0, rewritten = 0;
    void add(const FrameSplit& o) {
        frames += o.frames;
        decode_ms += o.decode_ms, steps_ms += o.steps_ms, encode_ms += o.encode_ms, collect_ms += o.collect_ms;
        collections += o.collections, bytes += o.bytes, rewritten += o.rewritten;
    }
};

struct PathResult {
    std::vector<double> frame_ms;  // one per timed frame
    double bytes_per_frame = -1;   // < 0: not measured on this path
    double gc_ms = -1;             // collection time inside the timed frames (< 0: n/a)
    double setup_ms = 0;           // building the world (untimed)
    // Σ (x + 3y) over the movers after the last frame, in px: equal on the
    // native, guile and reference paths when they agree (box2d: close).
    double checksum = std::numeric_limits<double>::quiet_NaN();
    int checksum_frames = 0;  // frames stepped (warm-up + timed) before the checksum
    std::string error;             // non-empty: the run failed
    std::string skipped;           // non-empty: stopped, a frame was too slow
    double spent_ms = 0;           // all frames stepped, warm-up included
    FrameSplit split;              // the guile path's timed frames
};

// The scene's bodies as the native path steps them (exact integers), and
// its shaped cells added to a grid made from its solid mask.
std::vector<ds::Body> to_bodies(const Scene& scene);
void add_shapes(ds::TileGrid& grid, const Scene& scene);
// The scenes' bounce update after a frame (Scene::bounce): an axis whose
// velocity a collision zeroed turns round to rvx / rvy, whose signs it flips.
void bounce(std::vector<ds::Body>& bodies, std::vector<int64_t>& rvx, std::vector<int64_t>& rvy);

// A scene as the native path steps it: its grid with the shaped cells
// added, a World on that grid, and the bounce scenes' turn-round speeds.
// Not copyable: world.grid points at grid.
struct NativeScene {
    explicit NativeScene(const Scene& scene);
    NativeScene(const NativeScene&) = delete;
    NativeScene& operator=(const NativeScene&) = delete;
    ds::TileGrid grid;
    ds::World world;
    std::vector<int64_t> rvx, rvy;
};

// ds::World + ds::Frame::step, one call per frame.
PathResult run_native(const Scene& scene, const RunConfig& cfg);
// The same body array, x += vx and y += vy (ds::Num) per body: a floor.
PathResult run_bare(const Scene& scene, const RunConfig& cfg);
// (step-scene scene dt) from (downstroke physics), or from
// (downstroke reference) when `reference`, in a Scheme loop.
PathResult run_guile(const Scene& scene, const RunConfig& cfg, bool reference);

#if DS_BENCH_HAVE_BOX2D
// Box2D's defaults (continuous collision on), or with continuous collision
// off (`discrete`: no time-of-impact pass, fast bodies may tunnel).
PathResult run_box2d(const Scene& scene, const RunConfig& cfg, bool discrete);
std::string box2d_version();
#endif

#if DS_BENCH_HAVE_BOX2D3
// Box2D v3 with its defaults (path_box2d3.cpp), on `workers` threads
// (1: no task system, the caller's thread).
PathResult run_box2d3(const Scene& scene, const RunConfig& cfg, int workers);
std::string box2d3_version();
#endif

}  // namespace bench
