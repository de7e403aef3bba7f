// SPDX-License-Identifier: MIT
#include "image_files.hpp"

#include <unordered_map>

#include "bounded_file.hpp"

namespace ds::build {

namespace {

// Why the file at `path` cannot be opened for reading, or "" when it can.
// Opening it is the whole check: it is closed again unread.
std::string open_problem(const std::string& path) {
    std::string error;
    return BoundedFile::open(path, error) ? std::string() : error;
}

// The same, asked once per path: an image collection's tiles, or several
// tilesets, often share a file.
class OpenProblems {
public:
    const std::string& of(const std::string& path) {
        auto it = known_.find(path);
        if (it == known_.end()) it = known_.emplace(path, open_problem(path)).first;
        return it->second;
    }

private:
    std::unordered_map<std::string, std::string> known_;
};

// A failing picture of `owner` (already worded, "tileset 'terrain'"): the
// load's error when strict, else the map's warning with what follows for
// the drawing (`effect`) and how many more of its pictures fail (`more`).
void report(const LoadState& s, Tilemap& map, const std::string& owner, const std::string& path,
            const std::string& problem, size_t more, const char* effect) {
    const std::string message = owner + ": image '" + path + "' cannot be opened: " + problem;
    if (s.options.strict) throw MapError(map.path, 0, message);
    map.warnings.push_back(map.path + ": " + message +
                           (more > 0 ? " (and " + std::to_string(more) + " more of its tiles' images)" : "") +
                           "; " + effect);
}

std::string tileset_name(const Tileset& ts) {
    return "tileset '" + ts.name + "'" + (ts.source.empty() ? "" : " (" + ts.source + ")");
}

void check_tileset(const LoadState& s, Tilemap& map, const Tileset& ts, OpenProblems& problems) {
    std::string first_path, first_problem, owner;
    size_t failing = 0;
    const auto check = [&](const std::string& image, const std::string& who) {
        if (image.empty()) return;  // an image embedded in the file, or none
        const std::string path = tileset_image_path(ts, image);
        const std::string& problem = problems.of(path);
        if (problem.empty()) return;
        if (s.options.strict) report(s, map, who, path, problem, 0, "");
        if (failing++ == 0) first_path = path, first_problem = problem, owner = who;
    };
    check(ts.image, tileset_name(ts));
    for (const TileInfo& t : ts.tiles) check(t.image, tileset_name(ts) + ", tile " + std::to_string(t.id));
    if (failing > 0)
        report(s, map, owner, first_path, first_problem, failing - 1, "its tiles cannot be drawn");
}

void check_layers(const LoadState& s, Tilemap& map, const std::vector<LayerInfo>& layers,
                  OpenProblems& problems) {
    for (const LayerInfo& l : layers) {
        if (l.kind == LayerKind::Group) check_layers(s, map, l.children, problems);
        if (l.kind != LayerKind::Image || l.image.empty()) continue;
        const std::string path = layer_image_path(map, l.image);
        if (const std::string& problem = problems.of(path); !problem.empty())
            report(s, map, "image layer '" + l.name + "'", path, problem, 0, "the layer cannot be drawn");
    }
}

}  // namespace

void check_image_files(const LoadState& s, Tilemap& map) {
    OpenProblems problems;
    for (const Tileset& ts : map.tilesets) check_tileset(s, map, ts, problems);
    check_layers(s, map, map.layer_tree, problems);
}

}  // namespace ds::build
