// SPDX-License-Identifier: MIT
// Draws maps whole with the engine and with Tiled's own renderer,
// tmxrasterizer, and compares the two pictures pixel by pixel (issue 34).
//
//   downstroke-tiled-oracle [--keep DIR] [--doc DIR] MAP.tmx|DIR ...
//
// A directory stands for every *.tmx and *.tmj in it (not below): Tiled's
// JSON twins of the TMX maps (tiled --export-map json) check the JSON reader
// reads every drawing attribute the TMX reader does. Tiled's picture
// covers what reaches past the map's edges, so only the map's own area is
// compared; it is clear where nothing is drawn and half-clear under a
// layer's opacity, so it is laid over the engine's background colour (the
// map's, else the engine's) first. Every pixel must then match within
// kTolerance per channel, except that a stretched or turned tile object may
// differ on its edge pixels (the two renderers sample them differently):
// pixels next to such an object's outline are left out. Exits 0 when every
// map matched, 1 when one did not, 77 (CTest's skip) when tmxrasterizer is
// not installed. --doc DIR also writes, for each map, DIR/render-NAME.png:
// the engine's picture and Tiled's side by side, each kDocScale times.
#include <SDL.h>
#include <SDL_image.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "canvas.hpp"
#include "constants.hpp"
#include "scene_draw.hpp"
#include "tile_art.hpp"
#include "tilemap/map_objects.hpp"
#include "tilemap/tilemap.hpp"

namespace fs = std::filesystem;
using namespace ds;
using namespace ds::render;

namespace {

constexpr int kTolerance = 2;       // per channel: Qt's and our rounding of opacity differ by 1
constexpr int kExitSkip = 77;      // CTest's SKIP_RETURN_CODE
constexpr int kDocScale = 3;       // the docs' pictures: small maps, shown large enough to see a pixel
constexpr int kDocGap = 4;         // px between the two pictures, at scale 1

bool have_rasterizer() { return std::system("command -v tmxrasterizer >/dev/null 2>&1") == 0; }

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// The margins tmxrasterizer adds around the map for layer offsets
// (Map::computeLayerOffsetMargins): the largest ceil(-offset) left and top.
std::pair<int, int> tiled_margins(const std::vector<LayerInfo>& tree, double ox, double oy, int& left, int& top) {
    for (const LayerInfo& l : tree) {
        const double x = ox + l.offset_x, y = oy + l.offset_y;
        if (l.kind == LayerKind::Group) {
            tiled_margins(l.children, x, y, left, top);
            continue;
        }
        left = std::max(left, int(std::ceil(-x)));
        top = std::max(top, int(std::ceil(-y)));
    }
    return {left, top};
}

uint32_t at(SDL_Surface* s, int x, int y) {
    return reinterpret_cast<const uint32_t*>(static_cast<const uint8_t*>(s->pixels) + y * s->pitch)[x];
}

// The canvas pixels within one px of a stretched or turned tile object's
// outline: the renderers may sample them differently.
std::vector<uint8_t> edge_mask(const Tilemap& map, int w, int h) {
    std::vector<uint8_t> mask(size_t(w) * h, 0);
    for (const ObjectLayer& layer : map.object_layers)
        for (const MapObject& o : layer.objects) {
            if (o.shape != ObjectShape::Tile) continue;
            const TileObjectBox b = tile_object_box(map, o);
            const auto [pw, ph] = tile_picture_size(map, o.gid);
            const bool plain = b.rotation == 0 && b.width == pw && b.height == ph &&
                               b.left == std::floor(b.left) && b.top == std::floor(b.top);
            if (plain) continue;
            const double rad = b.rotation * M_PI / 180, c = std::cos(rad), s = std::sin(rad);
            // Walk the outline finely and mark each pixel it passes and its neighbours.
            const double corners[5][2] = {{b.left, b.top}, {b.left + b.width, b.top},
                                          {b.left + b.width, b.top + b.height}, {b.left, b.top + b.height},
                                          {b.left, b.top}};
            for (int k = 0; k < 4; ++k) {
                const double len = std::hypot(corners[k + 1][0] - corners[k][0], corners[k + 1][1] - corners[k][1]);
                const int steps = int(len * 4) + 1;
                for (int i = 0; i <= steps; ++i) {
                    const double t = double(i) / steps;
                    const double x = corners[k][0] + t * (corners[k + 1][0] - corners[k][0]) - b.pivot_x;
                    const double y = corners[k][1] + t * (corners[k + 1][1] - corners[k][1]) - b.pivot_y;
                    const int px = int(std::floor(b.pivot_x + x * c - y * s));
                    const int py = int(std::floor(b.pivot_y + x * s + y * c));
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx)
                            if (px + dx >= 0 && py + dy >= 0 && px + dx < w && py + dy < h)
                                mask[size_t(py + dy) * w + px + dx] = 1;
                }
            }
        }
    return mask;
}

bool has_tile_objects(const ObjectLayer& l) {
    for (const MapObject& o : l.objects)
        if (o.shape == ObjectShape::Tile) return true;
    return false;
}

void collect(const std::vector<LayerInfo>& tree, std::vector<const LayerInfo*>& out) {
    for (const LayerInfo& l : tree) {
        out.push_back(&l);
        collect(l.children, out);
    }
}

// Tiled draws shape and text objects; the engine leaves them to the game.
// Layers holding only those are hidden from tmxrasterizer (--hide-layer,
// by name: only when every layer of that name is such a layer); the rest
// of them are masked out of the comparison, with kShapeMargin px around.
constexpr int kShapeMargin = 16;  // a point's pin and a shape's outline reach past its box

std::string hidden_layers(const Tilemap& map, std::vector<const MapObject*>& masked) {
    std::vector<const LayerInfo*> all;
    collect(map.layer_tree, all);
    const auto only_shapes = [&](const LayerInfo* l) {
        return l->kind == LayerKind::Object && !has_tile_objects(map.object_layers[l->index]);
    };
    std::string args;
    for (const LayerInfo* l : all) {
        if (l->kind != LayerKind::Object) continue;
        bool hide = only_shapes(l);
        for (const LayerInfo* m : all)
            if (m->name == l->name && m->kind != LayerKind::Group && !only_shapes(m)) hide = false;
        if (hide) {
            args += " --hide-layer " + quoted(l->name);
            continue;
        }
        // Debian's tmxrasterizer (Tiled 1.8) draws a template instance as
        // a small square, not its tile: those are left out too.
        for (const MapObject& o : map.object_layers[l->index].objects)
            if ((o.shape != ObjectShape::Tile || !o.template_path.empty()) && o.visible) masked.push_back(&o);
    }
    return args;
}

void mask_shapes(const Tilemap& map, const std::vector<const MapObject*>& shapes, int w, int h,
                 std::vector<uint8_t>& mask) {
    for (const MapObject* o : shapes) {
        double x0 = o->x, y0 = o->y, x1 = o->x + o->width, y1 = o->y + o->height;
        if (o->shape == ObjectShape::Tile) {
            const TileObjectBox b = tile_object_box(map, *o);
            x0 = b.left, y0 = b.top, x1 = b.left + b.width, y1 = b.top + b.height;
        }
        for (const ObjectPoint& p : o->points)
            x0 = std::min(x0, o->x + p.x), y0 = std::min(y0, o->y + p.y), x1 = std::max(x1, o->x + p.x),
            y1 = std::max(y1, o->y + p.y);
        if (o->rotation != 0) {  // any turn stays within the box's circumscribed square
            const double r = std::hypot(x1 - o->x, y1 - o->y) + std::hypot(x0 - o->x, y0 - o->y);
            x0 = o->x - r, y0 = o->y - r, x1 = o->x + r, y1 = o->y + r;
        }
        for (int y = std::max(0, int(y0) - kShapeMargin); y < std::min(h, int(y1) + kShapeMargin); ++y)
            for (int x = std::max(0, int(x0) - kShapeMargin); x < std::min(w, int(x1) + kShapeMargin); ++x)
                mask[size_t(y) * w + x] = 1;
    }
}

// tmxrasterizer has no camera and draws no parallax: the engine's picture
// is taken with every factor 1 (map-draw checks parallax by its formula).
void without_parallax(std::vector<LayerInfo>& tree) {
    for (LayerInfo& l : tree) {
        l.parallax_x = l.parallax_y = 1;
        without_parallax(l.children);
    }
}

// One map: 0 when the pictures match, 1 when not, 2 when it could not be compared.
// Tiled's pixel (tx, ty) laid over the background `bg` (clear beyond its
// picture): its picture is clear where nothing is drawn.
Rgba tiled_at(SDL_Surface* tiled, int tx, int ty, Rgba bg) {
    const uint32_t p = tx < tiled->w && ty < tiled->h ? at(tiled, tx, ty) : 0;
    const unsigned a = p >> 24;
    const auto over = [&](unsigned src, unsigned dst) { return uint8_t((src * a + dst * (255 - a) + 127) / 255); };
    return {over(p >> 16 & 0xff, bg.r), over(p >> 8 & 0xff, bg.g), over(p & 0xff, bg.b), 255};
}

// The engine's picture (left) and Tiled's laid over the same background
// (right), side by side and scaled up, for render.org.
void write_doc_picture(const std::string& file, const Canvas& ours, SDL_Surface* tiled, int left, int top, Rgba bg) {
    const int w = ours.width(), h = ours.height();
    Canvas doc((2 * w + kDocGap) * kDocScale, h * kDocScale);
    doc.clear({255, 255, 255, 255});
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Rgba theirs = tiled_at(tiled, x + left, y + top, bg);
            doc.fill_rect(x * kDocScale, y * kDocScale, kDocScale, kDocScale, ours.pixel(x, y));
            doc.fill_rect((w + kDocGap + x) * kDocScale, y * kDocScale, kDocScale, kDocScale, theirs);
        }
    doc.save_png(file);
}

bool repeats_an_image(const std::vector<LayerInfo>& tree) {
    for (const LayerInfo& l : tree)
        if ((l.kind == LayerKind::Image && (l.repeat_x || l.repeat_y)) || repeats_an_image(l.children)) return true;
    return false;
}

// What tmxrasterizer is given for `path`: the map itself, except that Tiled
// 1.8's JSON reader drops an image layer's repeatx/repeaty (later Tiled reads
// them): a .tmj twin with a repeated image layer is checked against Tiled's
// picture of its .tmx.
std::string oracle_input(const std::string& path, const Tilemap& map) {
    fs::path twin = fs::path(path).replace_extension(".tmx");
    std::error_code ec;
    if (fs::path(path).extension() == ".tmj" && repeats_an_image(map.layer_tree) && fs::exists(twin, ec))
        return twin.string();
    return path;
}

int compare(const std::string& path, const std::string& keep, const std::string& doc_dir) {
    Tilemap map;
    try {
        map = load_tilemap(path);
    } catch (const std::exception& e) {
        std::printf("ERROR %s: %s\n", path.c_str(), e.what());
        return 2;
    }
    const std::string base = fs::path(path).stem().string() + (fs::path(path).extension() == ".tmj" ? "-json" : "");
    const std::string tiled_png = (fs::path(keep) / (base + ".tiled.png")).string();
    const std::string ours_png = (fs::path(keep) / (base + ".engine.png")).string();
    std::vector<const MapObject*> shapes;
    const std::string hide = hidden_layers(map, shapes);
    const std::string cmd = "QT_QPA_PLATFORM=offscreen tmxrasterizer --no-smoothing" + hide + " " +
                            quoted(oracle_input(path, map)) + " " +
                            quoted(tiled_png) + " >/dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) {
        std::printf("ERROR %s: tmxrasterizer failed\n", path.c_str());
        return 2;
    }
    SDL_Surface* raw = IMG_Load(tiled_png.c_str());
    SDL_Surface* tiled = raw ? SDL_ConvertSurfaceFormat(raw, SDL_PIXELFORMAT_ARGB8888, 0) : nullptr;
    if (raw) SDL_FreeSurface(raw);
    if (!tiled) {
        std::printf("ERROR %s: cannot read %s\n", path.c_str(), tiled_png.c_str());
        return 2;
    }
    without_parallax(map.layer_tree);
    const int w = map.width * map.tile_width, h = map.height * map.tile_height;
    int left = 0, top = 0;
    tiled_margins(map.layer_tree, 0, 0, left, top);
    Canvas canvas(w, h);
    TileArt art;
    SceneView view;
    view.map = &map;
    try {
        draw_scene(canvas, art, view);
    } catch (const std::exception& e) {
        std::printf("ERROR %s: %s\n", path.c_str(), e.what());
        SDL_FreeSurface(tiled);
        return 2;
    }
    canvas.save_png(ours_png);
    const Rgba bg = map.background ? Rgba{map.background->r, map.background->g, map.background->b, 255} : kBackground;
    if (!doc_dir.empty())
        write_doc_picture((fs::path(doc_dir) / ("render-" + base + ".png")).string(), canvas, tiled, left, top, bg);
    std::vector<uint8_t> mask = edge_mask(map, w, h);
    mask_shapes(map, shapes, w, h, mask);
    // The differences, for a person to look at: the engine's picture dimmed,
    // each differing pixel red, each left-out one blue.
    Canvas diff(w, h);
    long differ = 0, skipped = 0;
    int fx = -1, fy = -1;
    Rgba first_ours{}, first_theirs{};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Rgba mine = canvas.pixel(x, y);
            diff.fill_rect(x, y, 1, 1, {uint8_t(mine.r / 3), uint8_t(mine.g / 3), uint8_t(mine.b / 3), 255});
            if (mask[size_t(y) * w + x]) {
                diff.fill_rect(x, y, 1, 1, {40, 40, 160, 255});
                ++skipped;
                continue;
            }
            const Rgba theirs = tiled_at(tiled, x + left, y + top, bg);
            const Rgba& ours = mine;
            if (std::abs(ours.r - theirs.r) > kTolerance || std::abs(ours.g - theirs.g) > kTolerance ||
                std::abs(ours.b - theirs.b) > kTolerance) {
                if (differ++ == 0) fx = x, fy = y, first_ours = ours, first_theirs = theirs;
                diff.fill_rect(x, y, 1, 1, {255, 0, 0, 255});
            }
        }
    SDL_FreeSurface(tiled);
    if (differ == 0) {
        std::printf("same %s (%dx%d px; %ld px left out: edges of stretched or turned objects, shapes)\n", path.c_str(), w, h,
                    skipped);
        return 0;
    }
    const std::string diff_png = (fs::path(keep) / (base + ".diff.png")).string();
    diff.save_png(diff_png);
    std::printf("DIFFERENT %s: %ld of %d px, the first at (%d, %d): engine #%02x%02x%02x, Tiled #%02x%02x%02x "
                "(pictures: %s, %s, the differences in red: %s)\n",
                path.c_str(), differ, w * h, fx, fy, first_ours.r, first_ours.g, first_ours.b, first_theirs.r,
                first_theirs.g, first_theirs.b, ours_png.c_str(), tiled_png.c_str(), diff_png.c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> maps;
    std::string keep, doc_dir;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--keep" && i + 1 < argc) {
            keep = argv[++i];
            continue;
        }
        if (a == "--doc" && i + 1 < argc) {
            doc_dir = argv[++i];
            continue;
        }
        std::error_code ec;
        if (fs::is_directory(a, ec)) {
            std::vector<std::string> found;
            for (const auto& e : fs::directory_iterator(a))
                if (e.path().extension() == ".tmx" || e.path().extension() == ".tmj") found.push_back(e.path().string());
            std::sort(found.begin(), found.end());
            maps.insert(maps.end(), found.begin(), found.end());
        } else {
            maps.push_back(a);
        }
    }
    if (!have_rasterizer()) {
        std::printf("skipped: tmxrasterizer (Debian's package tiled) is not installed, so there is no oracle\n");
        return kExitSkip;
    }
    if (keep.empty()) keep = (fs::temp_directory_path() / "downstroke-tiled-oracle").string();
    fs::create_directories(keep);
    SDL_Init(0);
    IMG_Init(IMG_INIT_PNG);
    int failed = 0, errors = 0;
    for (const std::string& m : maps) {
        const int r = compare(m, keep, doc_dir);
        failed += r == 1;
        errors += r == 2;
    }
    std::printf("%zu maps: %zu the same, %d different, %d not compared\n", maps.size(),
                maps.size() - failed - errors, failed, errors);
    return failed || errors ? 1 : 0;
}
