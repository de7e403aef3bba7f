// SPDX-License-Identifier: MIT
// downstroke-bench query: the spatial queries game logic calls every frame.
//
//   downstroke-bench query [--frames F] [--org FILE]
//
// Two cases, each native (the core's query.hpp on plain boxes) and through
// Scheme (the (downstroke query) procedures on plist entities), side by side
// in one run:
// - bullets × enemies: 2,000 moving 4×4 bullets against 500 moving 16×16
//   enemies in a 1280×720 field; the pair query against the same loop
//   written with aabb-overlap? in Scheme;
// - rays: 10,000 segments of up to 200 px a frame on the 60×15 platformer
//   level (bench/maps/platformer-60x15.tmx, the demo map as it was).
// Writes the "Queries" section of docs/benchmarks.org.
#include "query/queries.hpp"

#include <algorithm>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "common/guile_boot.hpp"
#include "common/org_file.hpp"
#include "common/run_info.hpp"
#include "common/timing.hpp"
#include "query.hpp"
#include "tilemap/tilemap.hpp"

namespace bench {

namespace {

constexpr int kBullets = 2000, kEnemies = 500, kRays = 10000;
constexpr double kFieldW = 1280, kFieldH = 720, kRayLength = 200;
// The issue's goals on this 2-core machine.
constexpr double kPairGoalMs = 0.5, kPairGoalRatio = 100, kRayGoalMs = 2;

const char* const kBegin = "# BEGIN downstroke-bench queries";
const char* const kEnd = "# END downstroke-bench queries";

struct Field {
    std::vector<ds::Box> bullets, enemies;
    std::vector<double> bvx, evx;
};

Field make_field(uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(0, kFieldW), y(0, kFieldH), v(-3, 3);
    Field f;
    for (int i = 0; i < kBullets; ++i) f.bullets.push_back({x(rng), y(rng), 4, 4}), f.bvx.push_back(v(rng));
    for (int i = 0; i < kEnemies; ++i) f.enemies.push_back({x(rng), y(rng), 16, 16}), f.evx.push_back(v(rng));
    return f;
}

void move(std::vector<ds::Box>& boxes, const std::vector<double>& vx) {
    for (size_t i = 0; i < boxes.size(); ++i) {
        boxes[i].x += vx[i];
        if (boxes[i].x < 0) boxes[i].x += kFieldW;
        if (boxes[i].x > kFieldW) boxes[i].x -= kFieldW;
    }
}

struct Result {
    Stats stats;
    size_t found = 0;  // pairs or hits in the last frame, as a check that both sides agree
};

Result native_pairs(int frames) {
    Field f = make_field(1);
    ds::PairQueryScratch scratch;
    std::vector<std::pair<uint32_t, uint32_t>> out;
    std::vector<double> ms;
    for (int k = 0; k < frames; ++k) {
        move(f.bullets, f.bvx);
        move(f.enemies, f.evx);
        out.clear();
        const int64_t t0 = now_ns();
        ds::overlapping_pairs(f.bullets, f.enemies, {}, scratch, out);
        ms.push_back((now_ns() - t0) / 1e6);
    }
    return {summarize(ms), out.size()};
}

std::vector<ds::Segment> rays(uint32_t seed, const ds::TileGrid& g) {
    std::mt19937 rng(seed);
    const double w = g.cols() * g.tile_width(), h = g.rows() * g.tile_height();
    std::uniform_real_distribution<double> x(0, w), y(0, h), d(-kRayLength, kRayLength);
    std::vector<ds::Segment> out;
    for (int i = 0; i < kRays; ++i) {
        const double x0 = x(rng), y0 = y(rng);
        out.push_back({x0, y0, x0 + d(rng), y0 + d(rng) + 1e-3});
    }
    return out;
}

Result native_rays(int frames, const ds::TileGrid& g) {
    const std::vector<ds::Segment> segs = rays(2, g);
    std::vector<ds::RayHit> hits;
    std::vector<double> ms;
    for (int k = 0; k < frames; ++k) {
        hits.clear();
        const int64_t t0 = now_ns();
        for (const ds::Segment& s : segs) ds::raycast_cells(g, s, true, hits);
        ms.push_back((now_ns() - t0) / 1e6);
    }
    return {summarize(ms), hits.size()};
}

// The Scheme side: builds the same field as plists and times one thunk per
// frame. Returns the frame times and the thunk's last result (a count).
const char* const kSchemeSetup = R"(
(use-modules (downstroke) (srfi srfi-1))
(define (boxes->entities boxes kind)
  (map (lambda (b) (list #:x (vector-ref b 0) #:y (vector-ref b 1) #:width (vector-ref b 2)
                         #:height (vector-ref b 3) #:kind kind))
       boxes))
(define (move-all es vxs)
  (map (lambda (e vx)
         (let* ((x (+ (entity-ref e #:x) vx))
                (x (cond ((< x 0) (+ x 1280.0)) ((> x 1280.0) (- x 1280.0)) (else x))))
           (entity-set e #:x x)))
       es vxs))
(define (scheme-loop bullets enemies)
  (let loop ((bs bullets) (n 0))
    (if (null? bs) n
        (let* ((b (car bs)) (bx (entity-ref b #:x)) (by (entity-ref b #:y))
               (bw (entity-ref b #:width)) (bh (entity-ref b #:height)))
          (loop (cdr bs)
                (fold (lambda (e n)
                        (if (aabb-overlap? bx by bw bh (entity-ref e #:x) (entity-ref e #:y)
                                           (entity-ref e #:width) (entity-ref e #:height))
                            (+ n 1) n))
                      n enemies))))))
)";

SCM boxes_scm(const std::vector<ds::Box>& boxes) {
    SCM out = SCM_EOL;
    for (size_t i = boxes.size(); i-- > 0;)
        out = scm_cons(scm_vector(scm_list_4(scm_from_double(boxes[i].x), scm_from_double(boxes[i].y),
                                             scm_from_double(boxes[i].w), scm_from_double(boxes[i].h))),
                       out);
    return out;
}
SCM doubles_scm(const std::vector<double>& v) {
    SCM out = SCM_EOL;
    for (size_t i = v.size(); i-- > 0;) out = scm_cons(scm_from_double(v[i]), out);
    return out;
}

SCM eval(const char* code) { return scm_c_eval_string(code); }

// mode 0: scene-pairs; 1: the aabb-overlap? loop.
Result scheme_pairs(int frames, int mode) {
    const Field f = make_field(1);
    SCM to_entities = eval("boxes->entities"), move_all = eval("move-all");
    SCM bullets = scm_call_2(to_entities, boxes_scm(f.bullets), eval("'bullet"));
    SCM enemies = scm_call_2(to_entities, boxes_scm(f.enemies), eval("'enemy"));
    SCM bvx = doubles_scm(f.bvx), evx = doubles_scm(f.evx);
    SCM pairs = eval("(lambda (bs es) (length (scene-pairs (make-scene #:entities (append bs es)) "
                     "'(#:kind . bullet) '(#:kind . enemy))))");
    SCM loop = eval("scheme-loop");
    std::vector<double> ms;
    size_t found = 0;
    for (int k = 0; k < frames; ++k) {
        bullets = scm_call_2(move_all, bullets, bvx);
        enemies = scm_call_2(move_all, enemies, evx);
        const int64_t t0 = now_ns();
        SCM n = scm_call_2(mode == 0 ? pairs : loop, bullets, enemies);
        ms.push_back((now_ns() - t0) / 1e6);
        found = scm_to_size_t(n);
    }
    return {summarize(ms), found};
}

Result scheme_rays(int frames, const ds::TileGrid& g, const std::string& map_path) {
    const std::vector<ds::Segment> segs = rays(2, g);
    SCM v = scm_c_make_vector(segs.size() * 4, SCM_BOOL_F);
    for (size_t i = 0; i < segs.size(); ++i) {
        scm_c_vector_set_x(v, 4 * i, scm_from_double(segs[i].x0));
        scm_c_vector_set_x(v, 4 * i + 1, scm_from_double(segs[i].y0));
        scm_c_vector_set_x(v, 4 * i + 2, scm_from_double(segs[i].x1));
        scm_c_vector_set_x(v, 4 * i + 3, scm_from_double(segs[i].y1));
    }
    SCM cast = eval(
        "(lambda (path) (let ((s (make-scene #:tilemap (load-tilemap path))))"
        "  (lambda (v) (let loop ((i 0) (n 0)) (if (= i (vector-length v)) n"
        "    (loop (+ i 4) (if (scene-raycast s (vector-ref v i) (vector-ref v (+ i 1))"
        "                                     (vector-ref v (+ i 2)) (vector-ref v (+ i 3))) (+ n 1) n)))))))");
    SCM run = scm_call_1(cast, scm_from_utf8_string(map_path.c_str()));
    std::vector<double> ms;
    size_t found = 0;
    for (int k = 0; k < frames; ++k) {
        const int64_t t0 = now_ns();
        found = scm_to_size_t(scm_call_1(run, v));
        ms.push_back((now_ns() - t0) / 1e6);
    }
    return {summarize(ms), found};
}

std::string row(const std::string& what, const Result& r, const std::string& note) {
    return "| " + what + " | " + sig3(r.stats.median_ms) + " | " + sig3(r.stats.min_ms) + " | " +
           std::to_string(r.found) + " | " + note + " |\n";
}

}  // namespace

int query_main(int argc, char** argv) {
    int frames = 60;
    std::string org = "docs/benchmarks.org";
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc) frames = count_arg(a, argv[++i], 1);
        else if (a == "--org" && i + 1 < argc) org = argv[++i];
        else {
            std::fprintf(stderr, "usage: downstroke-bench query [--frames F] [--org FILE]\n");
            return 2;
        }
    }
    const std::string command = command_line(argc, argv);
    const int64_t start = now_ns();
    const std::string map_path = DS_BENCH_SOURCE_DIR "/bench/maps/platformer-60x15.tmx";
    const ds::Tilemap map = ds::load_tilemap(map_path);
    const ds::TileGrid grid = map.solid_grid();
    ensure_guile();
    eval(kSchemeSetup);
    // Alternate native and Scheme so a noisy stretch of the machine hits both.
    const Result np = native_pairs(frames), sp = scheme_pairs(frames, 0);
    const int loop_frames = std::max(1, frames / 10);  // about 0.1 s a frame
    const Result sl = scheme_pairs(loop_frames, 1);
    const int ray_frames = std::max(1, frames / 4);  // 10,000 Scheme calls a frame
    const Result nr = native_rays(frames, grid), sr = scheme_rays(ray_frames, grid, map_path);
    RunInfo info = collect_run_info(command);
    info.total_s = (now_ns() - start) / 1e9;

    const double ratio = sl.stats.median_ms / sp.stats.median_ms;
    std::ostringstream o;
    o << kBegin << " (generated by downstroke-bench query; edits here are overwritten)\n* Queries\n\n"
      << "Game logic's queries (=(downstroke query)=, =src/query.*=), measured by\n"
         "=build/bin/downstroke-bench query= (=bench/query/=) on "
      << info.cpu << ", " << info.cores << " cores, " << info.date << ", " << info.build_type
      << ". Per frame: the median and min of " << frames << " frames (the\n"
         "Scheme loop: " << loop_frames << "; Scheme rays: " << ray_frames
      << "); found is the last frame's count of pairs or hits.\n\n"
      << "| case | median ms | min ms | found | note |\n|-\n"
      << row("pairs, native core (" + std::to_string(kBullets) + " × " + std::to_string(kEnemies) + " boxes)", np, "=overlapping_pairs=")
      << row("pairs, =scene-pairs= on plists", sp, "the query as a game calls it")
      << row("pairs, Scheme loop of =aabb-overlap?=", sl, sig3(ratio) + "× =scene-pairs=")
      << row(std::to_string(kRays) + " rays, native core", nr, "=raycast_cells=, first hit")
      << row(std::to_string(kRays) + " rays, =scene-raycast= calls", sr, "one Scheme call per ray")
      << "\nGoals (issue 20): pair query ≤ " << sig3(kPairGoalMs) << " ms/frame and ≥ " << sig3(kPairGoalRatio)
      << "× the Scheme loop; " << kRays << " rays ≤ " << sig3(kRayGoalMs) << " ms.\n"
      << "Whole run: " << sig3(info.total_s) << " s.\n"
      << kEnd << "\n";
    std::fputs(o.str().c_str(), stdout);
    if (np.found != sp.found)  // the same field after the same moves
        std::fprintf(stderr, "downstroke-bench query: the pair counts disagree (%zu native, %zu Scheme)\n",
                     np.found, sp.found);
    write_generated(org, kBegin, kEnd, o.str(), "#+title: Benchmarks\n\n");
    return 0;
}

}  // namespace bench
