// SPDX-License-Identifier: MIT
// Which frame of a Tiled tile animation shows at a moment of the game's
// clock: Tiled plays a tile's frames in order, each for its duration, and
// starts over; every cell holding that tile shows the same frame.
#pragma once
#include <cstdint>
#include <vector>

#include "tilemap/tilemap.hpp"

namespace ds::render {

// The local tile id of `frames` shown at `time_ms` (≥ 0; the game's frame
// number × its frame delay). Frames of zero duration never show; when all
// are zero (or there are none) the tile stays `still`.
uint32_t animation_frame(const std::vector<AnimationFrame>& frames, double time_ms, uint32_t still);

// Whether any tile of `ts` is animated: a tileset without animations costs
// the renderer nothing per tile.
bool has_animation(const Tileset& ts);

}  // namespace ds::render
