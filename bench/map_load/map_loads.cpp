// SPDX-License-Identifier: MIT
// downstroke-bench map-load: the cost of loading a map, TMX against JSON,
// per layer encoding, on the same maps:
// - the demo's platformer (100 × 15 cells, two tilesets, objects) as Tiled
//   itself wrote it in every encoding and exported it to JSON (the corpus
//   under tests/tilemap_corpus/maps/demo/);
// - a 1000 × 1000-cell map made here, the same cells written as TMX CSV and
//   TMX base64 and as JSON with an array and with base64, so the readers'
//   own cost shows at a size where it dominates.
// Per load: the median and min over rounds, TMX and JSON alternating.
// Writes the "Map loading" section of docs/benchmarks.org.
//
//   downstroke-bench map-load [--rounds R] [--org FILE]
#include "map_load/map_loads.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "common/org_file.hpp"
#include "common/run_info.hpp"
#include "common/timing.hpp"
#include "tilemap/tilemap.hpp"

namespace bench {

namespace {

constexpr int kBigSide = 1000;
const char* const kBegin = "# BEGIN downstroke-bench map-load";
const char* const kEnd = "# END downstroke-bench map-load";
const char* const kCorpus = "tests/tilemap_corpus/maps/demo/";

// The big map's cells: a floor, walls and a scatter of platforms, with
// gids 1-4 of one embedded tileset (gid 1 solid).
std::vector<uint32_t> big_cells() {
    std::vector<uint32_t> g(size_t(kBigSide) * kBigSide, 0);
    for (int r = 0; r < kBigSide; ++r)
        for (int c = 0; c < kBigSide; ++c)
            if (r == kBigSide - 1 || c == 0 || c == kBigSide - 1) g[size_t(r) * kBigSide + c] = 1;
            else if ((r * 7 + c * 13) % 29 == 0) g[size_t(r) * kBigSide + c] = 2 + (r + c) % 3;
    return g;
}

std::string csv(const std::vector<uint32_t>& g) {
    std::string out;
    for (size_t i = 0; i < g.size(); ++i) out += (i ? "," : "") + std::to_string(g[i]);
    return out;
}

std::string base64(const std::vector<uint32_t>& g) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string bytes;
    for (uint32_t v : g)
        for (int b = 0; b < 4; ++b) bytes += char(v >> (8 * b) & 0xff);  // little-endian, as Tiled
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t w = 0;
        for (size_t j = 0; j < 3; ++j) w = w << 8 | (j < n ? uint8_t(bytes[i + j]) : 0);
        for (size_t j = 0; j < 4; ++j) out += j <= n ? k[w >> (18 - 6 * j) & 63] : '=';
    }
    return out;
}

std::string big_tmx(const std::string& encoding, const std::string& data) {
    const std::string side = std::to_string(kBigSide);
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<map version=\"1.10\" orientation=\"orthogonal\" width=\"" +
           side + "\" height=\"" + side + "\" tilewidth=\"16\" tileheight=\"16\" infinite=\"0\">\n"
           " <tileset firstgid=\"1\" name=\"t\" tilewidth=\"16\" tileheight=\"16\" tilecount=\"4\" columns=\"4\">\n"
           "  <tile id=\"0\"><properties><property name=\"solid\" type=\"bool\" value=\"true\"/></properties></tile>\n"
           " </tileset>\n <layer id=\"1\" name=\"ground\" width=\"" + side + "\" height=\"" + side +
           "\">\n  <data encoding=\"" + encoding + "\">" + data + "</data>\n </layer>\n</map>\n";
}

std::string big_tmj(const std::string& data_member) {
    const std::string side = std::to_string(kBigSide);
    return "{\"type\":\"map\",\"orientation\":\"orthogonal\",\"width\":" + side + ",\"height\":" + side +
           ",\"tilewidth\":16,\"tileheight\":16,\"infinite\":false,\"tilesets\":[{\"firstgid\":1,\"name\":\"t\","
           "\"tilewidth\":16,\"tileheight\":16,\"tilecount\":4,\"columns\":4,\"tiles\":[{\"id\":0,\"properties\":"
           "[{\"name\":\"solid\",\"type\":\"bool\",\"value\":true}]}]}],\"layers\":[{\"type\":\"tilelayer\","
           "\"id\":1,\"name\":\"ground\",\"width\":" + side + ",\"height\":" + side + "," + data_member + "}]}";
}

std::string write_temp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("ds-bench-map-load-" + name);
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

// The median and min of one load of `path`, in ms, over `rounds` loads.
Stats time_loads(const std::string& path, int rounds) {
    std::vector<double> ms;
    for (int r = 0; r < rounds; ++r) {
        const int64_t t0 = now_ns();
        const ds::Tilemap m = ds::load_tilemap(path, ds::LoadOptions{});
        ms.push_back((now_ns() - t0) / 1e6);
        if (m.layers.empty()) throw std::runtime_error(path + ": no tile layer");
    }
    return summarize(ms);
}

struct Pair {
    std::string what, tmx, tmj;
    int rounds;
};

std::string row(const Pair& p, const Stats& x, const Stats& j) {
    return "| " + p.what + " | " + sig3(x.median_ms) + " | " + sig3(x.min_ms) + " | " + sig3(j.median_ms) + " | " +
           sig3(j.min_ms) + " | " + sig3(j.median_ms / x.median_ms) + " |\n";
}

}  // namespace

int map_load_main(int argc, char** argv) {
    int rounds = 40;
    std::string org = "docs/benchmarks.org";
    if (!rounds_and_org(argc, argv, "map-load", rounds, org)) return 2;
    const std::string command = command_line(argc, argv);
    const int64_t start = now_ns();
    const std::string demo = std::string(kCorpus) + "platformer.";
    std::vector<Pair> pairs;
    for (const char* enc : {"csv", "base64", "zlib", "gzip", "zstd"})
        pairs.push_back({std::string("platformer (100 × 15), ") + enc, demo + enc + ".tmx", demo + enc + ".tmj", rounds * 10});
    const std::vector<uint32_t> cells = big_cells();
    const std::string side = std::to_string(kBigSide) + " × " + std::to_string(kBigSide);
    pairs.push_back({side + ", CSV / array", write_temp("csv.tmx", big_tmx("csv", csv(cells))),
                     write_temp("array.tmj", big_tmj("\"data\":[" + csv(cells) + "]")), rounds / 4 + 1});
    const std::string b64 = base64(cells);
    pairs.push_back({side + ", base64", write_temp("base64.tmx", big_tmx("base64", b64)),
                     write_temp("base64.tmj", big_tmj("\"encoding\":\"base64\",\"data\":\"" + b64 + "\"")),
                     rounds / 4 + 1});
    std::ostringstream table;
    for (const Pair& p : pairs) {
        // TMX and JSON alternate round by round, so a noisy stretch hits both.
        std::vector<double> x, j;
        for (int r = 0; r < p.rounds; ++r) {
            x.push_back(time_loads(p.tmx, 1).median_ms);
            j.push_back(time_loads(p.tmj, 1).median_ms);
        }
        table << row(p, summarize(x), summarize(j));
    }
    RunInfo info = collect_run_info(command);
    info.total_s = (now_ns() - start) / 1e9;
    std::ostringstream o;
    o << kBegin << " (generated by downstroke-bench map-load; edits here are overwritten)\n* Map loading\n\n"
      << "One =ds::load_tilemap= of the same map as TMX and as JSON ([[file:tilemaps.org][tilemaps.org]]), "
         "measured by =build/bin/downstroke-bench map-load= (=bench/map_load/=) on "
      << info.cpu << ", " << info.cores << " cores, " << info.date << ", " << info.build_type
      << ". The platformer is the demo's map as Tiled 1.8 wrote it in each encoding and exported it to JSON "
         "(=tests/tilemap_corpus/maps/demo/=; its two tilesets are external files, read on each load); the "
      << side << " map is one tile layer written here, the same cells in both formats. Per load: the median "
         "and min over the rounds (" << rounds * 10 << " for the platformer, " << rounds / 4 + 1
      << " for the big map), the two formats alternating.\n\n"
      << "| map, encoding | TMX median ms | TMX min ms | JSON median ms | JSON min ms | JSON / TMX |\n|-\n"
      << table.str() << "\nWhole run: " << sig3(info.total_s) << " s.\n" << kEnd << "\n";
    std::fputs(o.str().c_str(), stdout);
    write_generated(org, kBegin, kEnd, o.str(), "#+title: Benchmarks\n\n");
    return 0;
}

}  // namespace bench
