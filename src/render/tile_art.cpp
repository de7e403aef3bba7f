// SPDX-License-Identifier: MIT
#include "tile_art.hpp"

#include <SDL_image.h>

#include <span>
#include <string_view>

#include "bounded_file.hpp"
#include "constants.hpp"
#include "image_header.hpp"
#include "render_error.hpp"
#include "tile_animation.hpp"

namespace ds::render {

namespace {

constexpr uint32_t kFlipBits = kFlipHorizontal | kFlipVertical | kFlipDiagonal;

// A 32-bit copy of `src` (any format) that blends only when it has alpha.
SDL_Surface* to_argb(SDL_Surface* src) {
    SDL_Surface* out = SDL_ConvertSurfaceFormat(src, SDL_PIXELFORMAT_ARGB8888, 0);
    if (!out) return nullptr;
    Uint32 key;
    const bool alpha = SDL_ISPIXELFORMAT_ALPHA(src->format->format) || SDL_GetColorKey(src, &key) == 0;
    SDL_SetSurfaceBlendMode(out, alpha ? SDL_BLENDMODE_BLEND : SDL_BLENDMODE_NONE);
    return out;
}

uint32_t get(const SDL_Surface* s, int x, int y) {
    return reinterpret_cast<const uint32_t*>(static_cast<const uint8_t*>(s->pixels) + y * s->pitch)[x];
}
void put(SDL_Surface* s, int x, int y, uint32_t p) {
    reinterpret_cast<uint32_t*>(static_cast<uint8_t*>(s->pixels) + y * s->pitch)[x] = p;
}

// The rect `r` of `image`, turned: destination (u, v) takes the source pixel
// found by undoing the vertical, then the horizontal, then the diagonal flip.
SDL_Surface* turned(SDL_Surface* image, const SDL_Rect& r, uint32_t flips) {
    const bool d = flips & kFlipDiagonal, h = flips & kFlipHorizontal, v = flips & kFlipVertical;
    const int w = d ? r.h : r.w, hgt = d ? r.w : r.h;
    SDL_Surface* out = SDL_CreateRGBSurfaceWithFormat(0, w, hgt, 32, SDL_PIXELFORMAT_ARGB8888);
    if (!out) return nullptr;
    SDL_BlendMode mode;
    SDL_GetSurfaceBlendMode(image, &mode);
    SDL_SetSurfaceBlendMode(out, mode);
    for (int y = 0; y < hgt; ++y)
        for (int x = 0; x < w; ++x) {
            const int ux = h ? w - 1 - x : x, uy = v ? hgt - 1 - y : y;
            const int sx = d ? uy : ux, sy = d ? ux : uy;
            put(out, x, y, get(image, r.x + sx, r.y + sy));
        }
    return out;
}

std::string key_text(const MapColor& c) {
    return std::to_string(c.r) + ',' + std::to_string(c.g) + ',' + std::to_string(c.b);
}

// The colour key as Tiled applies it: every opaque pixel of exactly that
// colour becomes clear, and the picture then blends.
void clear_key(SDL_Surface* img, const MapColor& c) {
    const uint32_t key = 0xff000000u | uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b;
    for (int y = 0; y < img->h; ++y)
        for (int x = 0; x < img->w; ++x)
            if (get(img, x, y) == key) put(img, x, y, 0);
    SDL_SetSurfaceBlendMode(img, SDL_BLENDMODE_BLEND);
}

// The file's header, read before anything is decoded, within the bounds:
// a RenderError naming the file otherwise (not a file, unreadable, larger
// than kMaxImageFileBytes, not an image, cut short, or larger than
// kMaxImageSidePx / kMaxImageDecodedBytes). `file` keeps the bytes read:
// the whole file, which is what is decoded.
ImageHeader checked_header(const std::string& path, const char* what, std::string& file) {
    const std::string named = std::string(what) + " '" + path + "'";
    std::string error;
    auto bytes = read_bounded_file(path, kMaxImageFileBytes, "an image file may hold", error);
    if (!bytes) throw RenderError("cannot read " + named + ": " + error);
    file = std::move(*bytes);
    const std::span<const uint8_t> head(reinterpret_cast<const uint8_t*>(file.data()), file.size());
    ImageHeader h;
    std::string why;
    if (!read_image_header(head, h, why)) throw RenderError("cannot read " + named + ": " + why);
    const std::string size = std::to_string(h.width) + "x" + std::to_string(h.height) + " px";
    if (h.width > kMaxImageSidePx || h.height > kMaxImageSidePx)
        throw RenderError("refusing " + named + ": its " + h.format + " header declares " + size +
                          ", more than the limit of " + std::to_string(kMaxImageSidePx) + " px a side");
    if (h.width * h.height * 4 > kMaxImageDecodedBytes)
        throw RenderError("refusing " + named + ": its " + h.format + " header declares " + size + ", " +
                          std::to_string(h.width * h.height * 4 >> 20) + " MiB decoded, more than the limit of " +
                          std::to_string(kMaxImageDecodedBytes >> 20) + " MiB");
    // SDL_image 2.6's GIF decoder writes past its buffers on hostile LZW data
    // whatever the header says (fuzz_decode.cpp found two such files in
    // minutes; tests/fuzz/regressions/decode/crash-gif-*): a GIF is not
    // handed to it. Tiled's tilesets are PNG; a GIF converts losslessly.
    if (std::string_view(h.format) == "GIF")
        throw RenderError("refusing " + named +
                          ": GIF is not loaded (SDL_image's GIF decoder is unsafe on hostile files); convert it to PNG");
    return h;
}

// SDL_image's name for the format read_image_header found: the decoder it
// is given to, rather than one it guesses from the bytes again.
const char* sdl_image_type(const ImageHeader& h) {
    return std::string_view(h.format) == "JPEG" ? "JPG" : h.format;
}

}  // namespace

bool tile_rect(const Tileset& ts, int image_w, int image_h, uint32_t id, SDL_Rect& out, int columns) {
    const int tw = ts.tile_width, th = ts.tile_height;
    if (tw <= 0 || th <= 0) return false;
    if (columns <= 0) columns = (image_w - 2 * ts.margin + ts.spacing) / (tw + ts.spacing);
    if (columns <= 0 || id >= tiles_in_image(ts, image_w, image_h, columns)) return false;
    const int64_t col = id % uint32_t(columns), row = id / uint32_t(columns);
    const int64_t x = ts.margin + col * (tw + ts.spacing), y = ts.margin + row * (th + ts.spacing);
    out = {int(x), int(y), tw, th};
    return true;
}

TileArt::~TileArt() {
    for (auto& [_, tiles] : sheets_)
        for (auto& [_, s] : tiles) SDL_FreeSurface(s);
    for (auto& [_, s] : images_) SDL_FreeSurface(s);
}

SDL_Surface* TileArt::image(const std::string& path, const std::optional<MapColor>& trans, const char* what) {
    const std::string key = trans ? path + '\x1f' + key_text(*trans) : path;
    if (auto it = images_.find(key); it != images_.end()) return it->second;
    std::string file;
    const ImageHeader header = checked_header(path, what, file);
    // Decoded from the bytes checked: the file is read once, and SDL_image
    // cannot read more of it than was.
    SDL_Surface* raw = IMG_LoadTyped_RW(SDL_RWFromConstMem(file.data(), int(file.size())), 1, sdl_image_type(header));
    if (!raw) throw RenderError(std::string("cannot read ") + what + " '" + path + "': " + IMG_GetError());
    if (raw->w != header.width || raw->h != header.height) {  // a decoder that disagrees with the header
        const std::string got = std::to_string(raw->w) + "x" + std::to_string(raw->h);
        SDL_FreeSurface(raw);
        throw RenderError(std::string("cannot read ") + what + " '" + path + "': it decoded to " + got +
                          " px, its header says " + std::to_string(header.width) + "x" + std::to_string(header.height));
    }
    SDL_Surface* img = to_argb(raw);
    SDL_FreeSurface(raw);
    if (!img) throw RenderError(std::string("cannot convert ") + what + " '" + path + "': " + SDL_GetError());
    if (trans) clear_key(img, *trans);
    images_.emplace(key, img);
    return img;
}

SDL_Surface* TileArt::picture(const std::string& path, const std::optional<MapColor>& trans, int declared_w,
                              int declared_h, const char* what) {
    SDL_Surface* img = image(path, trans, what);
    note_size(path, img, declared_w, declared_h, what);
    return img;
}

bool TileArt::note_size(const std::string& path, SDL_Surface* img, int declared_w, int declared_h, const char* what) {
    if (declared_w <= 0 || declared_h <= 0 || (img->w == declared_w && img->h == declared_h)) return true;
    if (warned_.insert(path).second)
        warnings_.push_back(std::string(what) + " '" + path + "' is " + std::to_string(img->w) + "x" +
                            std::to_string(img->h) + " px, but the map declares " + std::to_string(declared_w) + "x" +
                            std::to_string(declared_h) + "; drawn at its real size, as Tiled does");
    return false;
}

SDL_Surface* TileArt::cut(const Tileset& ts, uint32_t local_id, uint32_t flips) {
    SDL_Rect r;
    SDL_Surface* img;
    if (ts.image.empty()) {  // an image collection: each tile its own picture
        const TileInfo* info = ts.tile(local_id);
        if (!info || info->image.empty()) return nullptr;
        const std::string path = tileset_image_path(ts, info->image);
        img = image(path, ts.trans, "tileset image");
        note_size(path, img, info->image_width, info->image_height, "tileset image");
        r = {0, 0, img->w, img->h};
    } else {
        const std::string path = tileset_image_path(ts, ts.image);
        img = image(path, ts.trans, "tileset image");
        // Tiled cuts an image whose size is not the one its tileset declares
        // by its real size, counting its columns anew.
        const bool as_declared = note_size(path, img, ts.image_width, ts.image_height, "tileset image");
        if (!tile_rect(ts, img->w, img->h, local_id, r, as_declared ? ts.columns : 0)) return nullptr;
    }
    return turned(img, r, flips);
}

void TileArt::bind(const Tilemap* map) {
    map_ = map;
    bound_.clear();
    animated_.clear();
    if (!map) return;
    for (const Tileset& ts : map->tilesets) {
        const std::string key = ts.image_dir + '\x1f' + ts.image + '\x1f' + ts.name + '\x1f' +
                                std::to_string(ts.firstgid) + '\x1f' + std::to_string(ts.tile_width) +
                                'x' + std::to_string(ts.tile_height) + '\x1f' +
                                std::to_string(ts.margin) + ',' + std::to_string(ts.spacing) + ',' +
                                std::to_string(ts.columns) + (ts.trans ? '\x1f' + key_text(*ts.trans) : "");
        bound_.push_back(&sheets_[key]);
        animated_.push_back(has_animation(ts));
    }
}

SDL_Surface* TileArt::tile(uint32_t raw_gid, double time_ms) {
    const uint32_t gid = raw_gid & kGidMask;
    if (gid == 0 || !map_) return nullptr;
    const Tileset* ts = map_->tileset_for(gid);
    if (!ts) return nullptr;
    const size_t which = size_t(ts - map_->tilesets.data());
    Sheet& sheet = *bound_[which];
    uint32_t local = gid - ts->firstgid;
    if (animated_[which])
        if (const TileInfo* info = ts->tile(local); info && !info->animation.empty())
            local = animation_frame(info->animation, time_ms, local);
    const uint32_t flips = raw_gid & kFlipBits;
    const uint64_t k = uint64_t(local) << 3 | flips >> 29;
    if (auto it = sheet.find(k); it != sheet.end()) return it->second;
    SDL_Surface* s = cut(*ts, local, flips);
    sheet.emplace(k, s);
    return s;
}

}  // namespace ds::render
