// SPDX-License-Identifier: MIT
#include "music_format.hpp"

#include <cctype>
#include <cstring>

#include "constants.hpp"

namespace ds::render {

namespace {

constexpr const char* kStreamed = "for streamed music";
constexpr const char* kModule = "for a tracker module";
constexpr const char* kMidi = "for MIDI";

constexpr MusicFormat kOgg{"Ogg", kMaxStreamedMusicBytes, kStreamed};
constexpr MusicFormat kWav{"WAV", kMaxStreamedMusicBytes, kStreamed};
constexpr MusicFormat kFlac{"FLAC", kMaxStreamedMusicBytes, kStreamed};
constexpr MusicFormat kMp3{"MP3", kMaxStreamedMusicBytes, kStreamed};
constexpr MusicFormat kMidiFormat{"MIDI", kMaxMidiFileBytes, kMidi};
constexpr MusicFormat kMod{"MOD", kMaxModuleFileBytes, kModule};
constexpr MusicFormat kXm{"XM", kMaxModuleFileBytes, kModule};
constexpr MusicFormat kS3m{"S3M", kMaxModuleFileBytes, kModule};
constexpr MusicFormat kIt{"IT", kMaxModuleFileBytes, kModule};

bool at(std::span<const uint8_t> b, size_t offset, const char* magic) {
    const size_t n = std::strlen(magic);
    return b.size() >= offset + n && std::memcmp(b.data() + offset, magic, n) == 0;
}

// A 31-sample MOD's signature: "M.K." and its kin, or a channel count
// ("6CHN", "8CHN", "16CH", "32CN"). The 15-sample MODs of 1987 have none,
// and are not recognised.
bool mod_signature(std::span<const uint8_t> b) {
    if (b.size() < 1084) return false;
    for (const char* s : {"M.K.", "M!K!", "M&K!", "FLT4", "FLT8", "CD81", "OKTA", "OCTA", "N.T."})
        if (at(b, 1080, s)) return true;
    const auto digit = [&](size_t i) { return std::isdigit(b[1080 + i]) != 0; };
    return (digit(0) && at(b, 1081, "CHN")) || (digit(0) && digit(1) && (at(b, 1082, "CH") || at(b, 1082, "CN")));
}

// MPEG audio: an ID3v2 tag, or a frame header's 11 sync bits and a layer.
bool mp3(std::span<const uint8_t> b) {
    return at(b, 0, "ID3") || (b.size() >= 2 && b[0] == 0xFF && (b[1] & 0xE0) == 0xE0 && (b[1] & 0x06) != 0);
}

}  // namespace

const MusicFormat* music_format(std::span<const uint8_t> b) {
    if (at(b, 0, "OggS")) return &kOgg;
    if (at(b, 0, "RIFF") && at(b, 8, "WAVE")) return &kWav;
    if (at(b, 0, "MThd") || (at(b, 0, "RIFF") && at(b, 8, "RMID"))) return &kMidiFormat;
    if (at(b, 0, "fLaC")) return &kFlac;
    if (at(b, 0, "Extended Module: ")) return &kXm;
    if (at(b, 0, "IMPM")) return &kIt;
    if (at(b, 44, "SCRM")) return &kS3m;
    if (mod_signature(b)) return &kMod;
    if (mp3(b)) return &kMp3;
    return nullptr;
}

}  // namespace ds::render
