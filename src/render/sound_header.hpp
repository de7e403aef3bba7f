// What a sound file says of itself before it is decoded: WAV (RIFF/WAVE, its
// fmt and data chunks) and Ogg Vorbis (the identification header, and the
// last page's granule position: the stream's length in samples). Pure
// arithmetic on bytes, no SDL: the sound bank checks the decoded size
// against the bound before SDL_mixer allocates it.
#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace ds::render {

struct SoundHeader {
    const char* format = "";  // "WAV" or "OGG"
    int64_t channels = 0, rate = 0;
    int64_t frames = 0;       // samples per channel
};

// `head`: the file's first bytes (up to kSoundHeaderBytes); `tail`: its last
// ones (up to kSoundTailBytes; an Ogg stream's length is in its last page);
// `file_size`: its whole size. False, with `why`, for a file that is neither
// format, cut short, or whose header lies: a data chunk larger than the
// file, a channel count or rate no decoder takes, a length past the file.
bool read_sound_header(std::span<const uint8_t> head, std::span<const uint8_t> tail, uint64_t file_size,
                       SoundHeader& out, std::string& why);

constexpr size_t kSoundHeaderBytes = 64 * 1024;
constexpr size_t kSoundTailBytes = 64 * 1024;
// The most channels and the highest rate a header may declare: 8 channels
// (7.1) and 384 kHz are the most any recording format writes.
constexpr int64_t kMaxSoundChannels = 8;
constexpr int64_t kMaxSoundRate = 384000;

}  // namespace ds::render
