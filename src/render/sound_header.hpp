// SPDX-License-Identifier: MIT
// What a sound file says of itself before it is decoded: WAV (RIFF/WAVE, its
// fmt and data chunks) and Ogg Vorbis (the identification header, and the
// last page's granule position: the stream's length in samples). Pure
// arithmetic on bytes, no SDL: the sound bank checks the decoded size
// against the bound before SDL_mixer allocates it, and the differential fuzz
// target (tests/fuzz/fuzz_decode.cpp) holds every claim against what the
// decoders then produce.
#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace ds::render {

struct SoundHeader {
    const char* format = "";  // "WAV" or "OGG"
    int64_t channels = 0, rate = 0;
    int64_t frames = 0;       // samples per channel: at least as many as the decoder yields
    // Bytes a sample takes once decoded at the file's own rate, before the
    // mixer converts it: SDL's WAV decoder widens ADPCM and A-law/µ-law to
    // 16 bits and 24-bit PCM to 32; Ogg is decoded to 16 bits here.
    int64_t decoded_sample_bytes = 0;
};

// `file`: the whole file. False, with `why`, for a file that is neither
// format, cut short, or whose header lies or cannot be counted: a data
// chunk larger than the file, a channel count or rate no decoder takes, an
// encoding whose length is not known from its header, an Ogg stream whose
// last page is not a sound end of that stream.
bool read_sound_header(std::span<const uint8_t> file, SoundHeader& out, std::string& why);

// An Ogg page is at most 27 + 255 + 255 × 255 bytes: the last one starts
// within this many bytes of the end.
constexpr size_t kOggMaxPageBytes = 27 + 255 + 255 * 255;
// The most channels and the highest rate a header may declare: 8 channels
// (7.1) and 384 kHz are the most any recording format writes.
constexpr int64_t kMaxSoundChannels = 8;
constexpr int64_t kMaxSoundRate = 384000;

}  // namespace ds::render
