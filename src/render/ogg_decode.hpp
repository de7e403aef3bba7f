// SPDX-License-Identifier: MIT
// Ogg Vorbis sounds decoded here, with libvorbisfile, rather than by
// SDL_mixer: its decoder runs to the end of the stream whatever the header
// claimed, so a forged last page (a 30-minute file claiming one sample)
// would be decoded whole before any check could see it. This one stops the
// moment the stream outgrows the length the check accepted.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ds::render {

struct DecodedOgg {
    int channels = 0;
    long rate = 0;
    std::vector<int16_t> samples;  // interleaved, native-endian
};

// Decodes the Ogg Vorbis stream `file` (the whole file, in memory) to
// 16-bit samples, at most `max_frames` frames a channel. False, with `why`,
// when libvorbisfile cannot open or read it, when it is more than one
// stream or its channels and rate are not `channels` and `rate` (what the
// header check read), or when it holds more than `max_frames`.
bool decode_ogg(std::span<const uint8_t> file, int64_t channels, int64_t rate, int64_t max_frames, DecodedOgg& out,
                std::string& why);

}  // namespace ds::render
