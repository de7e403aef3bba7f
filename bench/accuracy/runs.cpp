// SPDX-License-Identifier: MIT
#include "accuracy/runs.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "accuracy/depth.hpp"
#include "common/timing.hpp"
#include "contacts.hpp"

namespace bench::accuracy {

namespace {

double depth_in_body(const ds::Body& b, const ds::Body& solid) {
    if (!ds::aabb_overlap(b, solid)) return 0;
    return std::min(overlap(b.x.v, b.w.v, solid.x.v, solid.w.v), overlap(b.y.v, b.h.v, solid.y.v, solid.h.v));
}

bool is_fixed(const ds::Body& b) { return b.immovable && b.collides(); }

// The solids a body may end up inside: the grid's cells and the immovable bodies.
struct Solids {
    const ds::TileGrid* grid = nullptr;
    std::vector<size_t> fixed;  // indices of the immovable bodies

    Solids(const ds::TileGrid* g, std::span<const ds::Body> bodies) : grid(g) {
        for (size_t i = 0; i < bodies.size(); ++i)
            if (is_fixed(bodies[i])) fixed.push_back(i);
    }

    // The deepest body `i` sits in a tile or an immovable body (in_tile says which).
    Depth depth_of(std::span<const ds::Body> bodies, size_t i) const {
        const ds::Body& b = bodies[i];
        Depth d;
        if (b.immovable) return d;
        if (grid) d.depth = depth_in_tiles(b, *grid);
        if (!b.collides()) return d;
        for (size_t k : fixed)
            if (const double in = depth_in_body(b, bodies[k]); in > d.depth) {
                d.depth = in;
                d.in_tile = false;
            }
        return d;
    }
};

// Replays the frame that left body `i` inside a solid with only that body
// and the immovables: see Depth::cause.
std::string cause(std::span<const ds::Body> before, size_t i, const Solids& solids, const Config& c) {
    ds::World alone;
    alone.grid = solids.grid;
    alone.bodies.push_back(before[i]);
    for (size_t k : solids.fixed) alone.bodies.push_back(before[k]);
    ds::Frame frame;
    frame.step(alone, c.options());
    if (Solids(solids.grid, alone.bodies).depth_of(alone.bodies, 0).depth == 0) return "pushed";
    return solids.depth_of(before, i).depth > 0 ? "carried" : "alone";
}

bool same_state(std::span<const ds::Body> a, std::span<const ds::Body> b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (ds::changed_fields(a[i], b[i]) != 0) return false;
    return true;
}

// Watches the frame-end positions for an exact repeat of period 1 or 2.
class RepeatWatch {
public:
    explicit RepeatWatch(long min_run) : min_run_(min_run) {}

    void observe(long frame, std::span<const ds::Body> bodies) {
        now_.clear();
        for (const ds::Body& b : bodies) now_.push_back(b.x.v), now_.push_back(b.y.v);
        for (int p = 1; p <= 2; ++p) track(p, frame, frame >= p && now_ == back_[p - 1]);
        back_[1].swap(back_[0]);
        back_[0].swap(now_);
    }

    long min_run() const { return min_run_; }

    // The run stopped inside a cycle of the whole state: the positional
    // repeat under way goes on to the end.
    void assume_periodic() {
        for (int p = 1; p <= 2 && first_.period == 0; ++p)
            if (run_start_[p - 1] >= 0) first_ = {p, run_start_[p - 1], false, -1};
    }

    Repeat result() const {
        Repeat r = first_;
        if (r.period != 0) r.held = run_start_[r.period - 1] == r.from;
        return r;
    }

private:
    void track(int p, long frame, bool repeats) {
        long& start = run_start_[p - 1];
        if (!repeats) {
            if (first_.period == p && start == first_.from && first_.broke_at < 0) first_.broke_at = frame;
            start = -1;
            return;
        }
        if (start < 0) start = frame - p;
        // Period 1 is also period 2: checked first, it wins a tie.
        if (first_.period == 0 && frame - start >= min_run_) first_ = {p, start, false, -1};
    }

    long min_run_;
    long run_start_[2] = {-1, -1};
    Repeat first_;
    std::vector<double> now_, back_[2];
};

struct DriftWatch {
    std::vector<ds::Body> start;
    double max_dy = 0, max_dx = 0;

    void observe(std::span<const ds::Body> bodies) {
        for (size_t i = 0; i < bodies.size(); ++i) {
            if (bodies[i].immovable) continue;
            max_dy = std::max(max_dy, std::fabs(bodies[i].y.v - start[i].y.v));
            max_dx = std::max(max_dx, std::fabs(bodies[i].x.v - start[i].x.v));
        }
    }
};

// Notes the deepest body this frame left inside a solid; returns how many were.
long watch_depth(Run& run, std::span<const ds::Body> before, std::span<const ds::Body> now, long t,
                 const Solids& solids, const Config& c) {
    long inside = 0;
    for (size_t i = 0; i < now.size(); ++i) {
        Depth d = solids.depth_of(now, i);
        if (d.depth > 0) ++inside;
        if (d.depth <= run.worst.depth) continue;
        d.frame = t;
        d.body = static_cast<long>(i);
        d.cause = cause(before, i, solids, c);
        run.worst = d;
    }
    return inside;
}

// The frames after a run stopped inside a cycle of period p repeat the
// last p frames: counts[1] is the last frame's, counts[0] the one before.
long cycle_count(const long counts[2], int p, long remaining) {
    if (p == 1) return remaining * counts[1];
    return (remaining + 1) / 2 * counts[0] + remaining / 2 * counts[1];
}

}  // namespace

Run run_scene(const Setup& s, const Config& c, long frames, bool shortcut) {
    Run run;
    run.scene = s.name;
    run.frames = frames;
    ds::World w = s.world();
    const ds::FrameOptions opts = c.options();
    ds::Frame frame;
    const Solids solids(s.grid.get(), w.bodies);
    run.movers = std::count_if(w.bodies.begin(), w.bodies.end(), [](const ds::Body& b) { return !b.immovable; });
    RepeatWatch repeat(std::max(10L, std::min(1000L, frames / 10)));
    DriftWatch drift{w.bodies};
    repeat.observe(0, w.bodies);
    std::vector<double> ms;
    ms.reserve(static_cast<size_t>(frames));
    std::vector<ds::Body> prev = w.bodies, prev2;  // the states one and two frames back
    long stop = frames, counts[2] = {0, 0};
    int cycle = 0;  // the period of the whole state's repeat, once seen
    for (long t = 1; t <= stop; ++t) {
        const int64_t t0 = now_ns();
        frame.step(w, opts);
        ms.push_back(static_cast<double>(now_ns() - t0) / 1e6);
        counts[0] = counts[1];
        counts[1] = watch_depth(run, prev, w.bodies, t, solids, c);
        run.inside += counts[1];
        drift.observe(w.bodies);
        repeat.observe(t, w.bodies);
        if (shortcut && cycle == 0) {
            cycle = same_state(w.bodies, prev) ? 1 : same_state(w.bodies, prev2) ? 2 : 0;
            // Watch the cycle long enough for the positional repeat to count.
            if (cycle) stop = std::min(frames, t + repeat.min_run() + 2);
        }
        prev2.swap(prev);
        prev = w.bodies;
        run.stepped = t;
    }
    if (run.stepped < frames) {
        repeat.assume_periodic();
        run.inside += cycle_count(counts, cycle, frames - run.stepped);
    }
    run.median_ms = summarize(std::move(ms)).median_ms;
    run.max_dy = drift.max_dy;
    run.max_dx = drift.max_dx;
    run.repeat = repeat.result();
    return run;
}

}  // namespace bench::accuracy
