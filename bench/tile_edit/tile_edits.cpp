// SPDX-License-Identifier: MIT
// downstroke-bench tile-edit: the cost of one tile edit, on the demo's
// platformer map (60 × 15 cells) and on a 1000 × 1000-cell map made in
// memory, two ways:
// - tilemap-set-tile from Scheme, each edit on the map the last one made
//   (what a game changing its level does);
// - native: the copy and ds::set_tile that tilemap-set-tile runs, without
//   Guile (copy a Tilemap and its TileGrid, edit both).
// Per edit: the median and min over rounds of kEditsPerRound edits.
// Writes the "Tile edits" section of docs/benchmarks.org.
//
//   downstroke-bench tile-edit [--rounds R] [--org FILE]
#include "tile_edit/tile_edits.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "common/guile_boot.hpp"
#include "common/org_file.hpp"
#include "common/run_info.hpp"
#include "common/timing.hpp"
#include "tilemap/tilemap.hpp"

namespace bench {

namespace {

// Enough edits per round that the clock's resolution and one GC pause do
// not dominate, few enough that a round of the big map stays short.
constexpr int kEditsPerRound = 200;
constexpr int kBigSide = 1000;

const char* const kBegin = "# BEGIN downstroke-bench tile-edit";
const char* const kEnd = "# END downstroke-bench tile-edit";

struct Cost {
    Stats us;  // per edit (Stats' _ms fields hold µs here)
};

// A floor along the bottom row, the rest empty: gid 1 solid.
ds::Tilemap big_map() {
    std::vector<uint32_t> gids(size_t(kBigSide) * kBigSide, 0);
    std::fill(gids.end() - kBigSide, gids.end(), 1u);
    return ds::make_tilemap(kBigSide, kBigSide, 16, 16, std::move(gids), {1});
}

// The cells the edits walk: along the map's bottom row, clearing and
// putting back a solid tile (gid).
uint32_t edit_gid(int k, uint32_t solid) { return k % 2 ? solid : 0; }

Cost native_edits(const ds::Tilemap& start, uint32_t solid, int rounds) {
    ds::Tilemap map = start;
    ds::TileGrid grid = map.solid_grid();
    std::vector<double> us;
    for (int r = 0; r < rounds; ++r) {
        const int64_t t0 = now_ns();
        for (int k = 0; k < kEditsPerRound; ++k) {
            ds::Tilemap next = map;  // as tilemap-set-tile copies its argument
            ds::TileGrid next_grid = grid;
            ds::set_tile(next, next_grid, 0, k % map.width, map.height - 1, edit_gid(k, solid));
            map = std::move(next);
            grid = std::move(next_grid);
        }
        us.push_back((now_ns() - t0) / 1e3 / kEditsPerRound);
    }
    return {summarize(us)};
}

Cost scheme_edits(const char* map_expr, uint32_t solid, int rounds) {
    SCM edit = scm_c_eval_string(
        "(lambda (m n solid)"
        "  (let ((w (tilemap-width m)) (row (- (tilemap-height m) 1)))"
        "    (let loop ((k 0) (m m))"
        "      (if (= k n) m (loop (+ k 1) (tilemap-set-tile m (modulo k w) row (if (odd? k) solid 0)))))))");
    SCM map = scm_c_eval_string(map_expr);
    std::vector<double> us;
    for (int r = 0; r < rounds; ++r) {
        const int64_t t0 = now_ns();
        map = scm_call_3(edit, map, scm_from_int(kEditsPerRound), scm_from_uint32(solid));
        us.push_back((now_ns() - t0) / 1e3 / kEditsPerRound);
    }
    return {summarize(us)};
}

std::string row(const std::string& what, const Cost& c, const std::string& note) {
    return "| " + what + " | " + sig3(c.us.median_ms) + " | " + sig3(c.us.min_ms) + " | " + note + " |\n";
}

// The first solid gid on the platformer map's bottom row (its ground).
uint32_t ground_gid(const ds::Tilemap& m) {
    const ds::TileLayer& l = m.layers.at(0);
    for (int c = 0; c < l.width; ++c)
        if (const uint32_t g = l.raw_gid(c, l.height - 1); g && m.gid_solid(g)) return g;
    return 0;
}

}  // namespace

int tile_edit_main(int argc, char** argv) {
    int rounds = 40;
    std::string org = "docs/benchmarks.org";
    if (!rounds_and_org(argc, argv, "tile-edit", rounds, org)) return 2;
    const std::string command = command_line(argc, argv);
    const int64_t start = now_ns();
    const std::string path = "demo/maps/platformer.tmx";
    const ds::Tilemap small = ds::load_tilemap(path), big = big_map();
    const uint32_t g = ground_gid(small);
    ensure_guile();
    scm_c_eval_string("(use-modules (downstroke))");
    const std::string small_expr = "(load-tilemap \"" + path + "\")";
    const std::string big_expr = "(let ((v (make-vector " + std::to_string(kBigSide * kBigSide) +
                                 " 0))) (vector-fill! v 1 " + std::to_string(kBigSide * (kBigSide - 1)) +
                                 ") (make-tilemap " + std::to_string(kBigSide) + " " + std::to_string(kBigSide) +
                                 " 16 16 v '(1)))";
    // Native and Scheme alternate map by map, so a noisy stretch hits both.
    const Cost ns = native_edits(small, g, rounds), ss = scheme_edits(small_expr.c_str(), g, rounds);
    const Cost nb = native_edits(big, 1, rounds), sb = scheme_edits(big_expr.c_str(), 1, rounds);
    RunInfo info = collect_run_info(command);
    info.total_s = (now_ns() - start) / 1e9;

    const std::string side = std::to_string(kBigSide);
    std::ostringstream o;
    o << kBegin << " (generated by downstroke-bench tile-edit; edits here are overwritten)\n* Tile edits\n\n"
      << "One tile edit, =tilemap-set-tile= (a new map sharing the old one's unchanged\n"
         "chunks, [[file:tilemaps.org][tilemaps.org]]) and the copy and =ds::set_tile= it runs, measured by\n"
         "=build/bin/downstroke-bench tile-edit= (=bench/tile_edit/=) on "
      << info.cpu << ", " << info.cores << " cores, " << info.date << ", " << info.build_type
      << ". Per edit: the median and min over " << rounds << " rounds of " << kEditsPerRound
      << " edits, each on the map the last one made, along the bottom row.\n\n"
      << "| case | median µs | min µs | note |\n|-\n"
      << row("platformer map (60 × 15), =tilemap-set-tile=", ss, "from Scheme")
      << row("platformer map, native copy + =set_tile=", ns, "no Guile")
      << row(side + " × " + side + " map, =tilemap-set-tile=", sb, "from Scheme")
      << row(side + " × " + side + " map, native copy + =set_tile=", nb, "no Guile")
      << "\nWhole run: " << sig3(info.total_s) << " s.\n"
      << kEnd << "\n";
    std::fputs(o.str().c_str(), stdout);
    write_generated(org, kBegin, kEnd, o.str(), "#+title: Benchmarks\n\n");
    return 0;
}

}  // namespace bench
