// SPDX-License-Identifier: MIT
// The pictures of a map's tiles, cut from its tilesets' images and turned by
// each gid's flip bits. Images are read the first time a tile of theirs is
// drawn (loading a map never needs them), and every cut and flip is kept, so
// a frame costs one lookup per tile drawn.
#pragma once
#include <SDL.h>

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "tilemap/tilemap.hpp"

namespace ds::render {

class TileArt {
public:
    TileArt() = default;
    ~TileArt();
    TileArt(const TileArt&) = delete;
    TileArt& operator=(const TileArt&) = delete;

    // Makes `map` the one tile() reads, resolving its tilesets once: call it
    // at the start of every frame drawn (a map is known by its tilesets'
    // contents, never by its address). nullptr unbinds.
    void bind(const Tilemap* map);

    // The picture for a raw gid of the bound map (flip bits applied:
    // diagonal first, then horizontal, then vertical, as Tiled does), or
    // nullptr for gid 0, no bound map, a gid no tileset holds, or a tile
    // outside its image. An animated tile shows its frame at `time_ms` of
    // the game's clock. Throws RenderError naming the image file when it
    // cannot be read.
    SDL_Surface* tile(uint32_t raw_gid, double time_ms = 0);

    // A whole image (an image layer's), read once per path and colour key:
    // pixels of the colour `trans` are clear. Throws RenderError naming the
    // file when it cannot be read.
    // The map's declared size (0: none) is checked as a tileset's is.
    // `what` names it in errors and warnings.
    SDL_Surface* picture(const std::string& path, const std::optional<MapColor>& trans, int declared_w = 0,
                         int declared_h = 0, const char* what = "image layer image");

    // What drawing found that the game should hear of, once per image: an
    // image whose real size is not the one the map declares. take_warnings
    // hands them over and forgets them.
    std::vector<std::string> take_warnings() { return std::exchange(warnings_, {}); }

    // How many images have been read (each file and colour key once).
    size_t images_loaded() const { return images_.size(); }

private:
    // Whether `img` has the size the map declares for it (or none is
    // declared); a warning, once per path, when not.
    bool note_size(const std::string& path, SDL_Surface* img, int declared_w, int declared_h, const char* what);
    // `what` names the image in errors ("tileset image").
    SDL_Surface* image(const std::string& path, const std::optional<MapColor>& trans, const char* what);
    SDL_Surface* cut(const Tileset& ts, uint32_t local_id, uint32_t flips);

    std::unordered_map<std::string, SDL_Surface*> images_;  // by path and colour key
    // By tileset (its identity as text: image folder, image, name, firstgid
    // and cut) then by local id and flips.
    using Sheet = std::unordered_map<uint64_t, SDL_Surface*>;
    std::unordered_map<std::string, Sheet> sheets_;
    const Tilemap* map_ = nullptr;
    std::vector<Sheet*> bound_;  // per tileset of map_
    std::vector<bool> animated_;  // per tileset of map_
    std::vector<std::string> warnings_;
    std::unordered_set<std::string> warned_;  // image paths warned of: has_animation
};

// Where local tile `id` sits in a single-image tileset of an image
// `image_w` × `image_h` px, in `columns` columns (0: as many as fit);
// false when it is beyond the image.
bool tile_rect(const Tileset& ts, int image_w, int image_h, uint32_t id, SDL_Rect& out, int columns);

}  // namespace ds::render
