// SPDX-License-Identifier: MIT
// Which music format a file holds, told by its first bytes, and how large a
// file of that format may be (constants.hpp says why each bound). Only the
// formats named here are handed to SDL_mixer: it takes anything else for a
// tracker module and gives it to libmodplug, which reads dozens of formats
// no check here knows.
#pragma once
#include <cstdint>
#include <span>

namespace ds::render {

struct MusicFormat {
    const char* name;   // "Ogg", "WAV", "FLAC", "MP3", "MIDI", "MOD", "XM", "S3M", "IT"
    int64_t max_bytes;  // the largest file of it loaded
    const char* bound;  // which bound that is, for the refusal: "for streamed music" …
};

// A MOD's signature is at byte 1080, after its title and 31 sample headers:
// recognising every format takes this much of the file's start.
constexpr size_t kMusicSniffBytes = 1084;

// The format of the file whose first bytes (up to kMusicSniffBytes) are
// `head`, or nullptr when it is none of them.
const MusicFormat* music_format(std::span<const uint8_t> head);

// The formats recognised, for the refusal of the rest.
constexpr const char* kMusicFormatNames = "Ogg Vorbis, WAV, FLAC, MP3, MIDI, MOD, XM, S3M or IT";

}  // namespace ds::render
