// SPDX-License-Identifier: MIT
#include "audio.hpp"

#include <SDL.h>
#include <SDL_mixer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>
#include <string_view>

#include "alsa_quiet.hpp"
#include "bounded_file.hpp"
#include "constants.hpp"
#include "music_format.hpp"
#include "ogg_decode.hpp"
#include "render_error.hpp"
#include "sound_header.hpp"

namespace ds::render {

namespace {

// CD rate: every device takes it natively, and 22050 Hz effects resample up
// by an exact factor of two.
constexpr int kFrequency = 44100;
// Stereo, because that is what devices expect; mono effects sit in the middle.
constexpr int kOutputChannels = 2;
// Samples per mix: about 23 ms at 44.1 kHz, so a sound starts within about
// one and a half frames at 60 fps, yet a busy machine does not underrun.
constexpr int kChunkSamples = 1024;
// Sounds at once: more than a crowded screen of coins and hits needs, few
// enough that mixing them all costs nothing.
constexpr int kMixChannels = 16;

struct ChunkFree {
    void operator()(Mix_Chunk* c) const { Mix_FreeChunk(c); }
};
using ChunkPtr = std::unique_ptr<Mix_Chunk, ChunkFree>;

// Opens SDL audio and the mixer on `driver` (nullptr: SDL's own choice).
// On failure nothing is left open and SDL_GetError() says why.
bool open_mixer(const char* driver) {
    if (driver) {
        // Override, not the default priority: an SDL_AUDIODRIVER in the
        // environment would otherwise win and a headless run would reach for
        // a real device.
        SDL_SetHintWithPriority(SDL_HINT_AUDIODRIVER, driver, SDL_HINT_OVERRIDE);
    }
    bool ok = SDL_InitSubSystem(SDL_INIT_AUDIO) == 0;
    // The driver is only read by that init: give the next one its own choice.
    if (driver) SDL_ResetHint(SDL_HINT_AUDIODRIVER);
    if (!ok) return false;
    if (Mix_OpenAudio(kFrequency, MIX_DEFAULT_FORMAT, kOutputChannels, kChunkSamples) == 0)
        return true;
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    return false;
}

std::span<const uint8_t> bytes_of(const std::string& s) {
    return {reinterpret_cast<const uint8_t*>(s.data()), s.size()};
}

// The whole of the `kind` ("sound", "music") file at `path`, which must be a
// regular file of at most `max_bytes` (its bound, named by `limit_name`);
// else RenderError naming the file.
std::string read_whole(const char* kind, const std::string& path, const BoundedFile& file, int64_t max_bytes,
                       const char* limit_name) {
    std::string error;
    auto bytes = file.read_all(max_bytes, limit_name, error);
    if (!bytes) throw RenderError(std::string(kind) + " " + path + ": " + error);
    return std::move(*bytes);
}

// The file at `path`, opened by the bounded reader (a regular file, without
// blocking); else RenderError naming it as a `kind` file.
BoundedFile open_file(const char* kind, const std::string& path) {
    std::string error;
    auto file = BoundedFile::open(path, error);
    if (!file) throw RenderError(std::string(kind) + " " + path + ": " + error);
    return std::move(*file);
}

// The header of the sound `file`, whose decoding — at its own rate, then as
// the mixer holds it, at kFrequency, kOutputChannels of 16 bits — fits in
// kMaxSoundDecodedBytes; else RenderError naming `path`. Read before
// anything is decoded.
SoundHeader checked_header(const std::string& path, const std::string& file) {
    SoundHeader h;
    std::string why;
    if (!read_sound_header(bytes_of(file), h, why)) throw RenderError("sound " + path + ": " + why);
    const double native = double(h.frames) * double(h.channels) * double(h.decoded_sample_bytes);
    const double mixed = double(h.frames) * kFrequency / double(h.rate) * kOutputChannels * 2;
    const double decoded = std::max(native, mixed);
    if (decoded > double(kMaxSoundDecodedBytes))
        throw RenderError("sound " + path + ": its " + h.format + " header declares " + std::to_string(h.frames) +
                          " samples at " + std::to_string(h.rate) + " Hz, " + std::to_string(int64_t(decoded) >> 20) +
                          " MiB decoded, more than the limit of " + std::to_string(kMaxSoundDecodedBytes >> 20) +
                          " MiB");
    return h;
}

void put_le(std::string& out, uint32_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(char(v >> (8 * i) & 0xff));
}

// The decoded Ogg `d` as a 16-bit PCM WAV in memory: what Mix_LoadWAV_RW
// converts to the mixer's format. A copy, so an Ogg sound briefly takes
// twice its decoded size, both within the bound the header was checked by.
std::string as_wav(const DecodedOgg& d) {
    const auto data_bytes = uint32_t(d.samples.size() * 2);
    std::string w = "RIFF";
    w.reserve(44 + data_bytes);
    put_le(w, 36 + data_bytes, 4);
    w += "WAVEfmt ";
    put_le(w, 16, 4);
    put_le(w, 1, 2);  // PCM
    put_le(w, uint32_t(d.channels), 2);
    put_le(w, uint32_t(d.rate), 4);
    put_le(w, uint32_t(d.rate * d.channels * 2), 4);
    put_le(w, uint32_t(d.channels * 2), 2);
    put_le(w, 16, 2);
    w += "data";
    put_le(w, data_bytes, 4);
    for (const int16_t v : d.samples) put_le(w, uint16_t(v), 2);
    return w;
}

// The chunk of the sound `file` whose header `h` passed: a WAV decoded by
// SDL_mixer, an Ogg here, stopping at the header's length (ogg_decode.hpp).
Mix_Chunk* decode_sound(const std::string& path, const std::string& file, const SoundHeader& h) {
    if (std::strcmp(h.format, "OGG") != 0) return Mix_LoadWAV_RW(SDL_RWFromConstMem(file.data(), int(file.size())), 1);
    DecodedOgg decoded;
    std::string why;
    if (!decode_ogg(bytes_of(file), h.channels, h.rate, h.frames, decoded, why))
        throw RenderError("sound " + path + ": " + why);
    const std::string wav = as_wav(decoded);
    decoded = {};
    return Mix_LoadWAV_RW(SDL_RWFromConstMem(wav.data(), int(wav.size())), 1);
}

// SDL_mixer's name for `format` (music_format.hpp): the decoder it is given
// to, rather than one SDL_mixer guesses from the bytes again.
Mix_MusicType mixer_type(const MusicFormat& format) {
    const std::string_view n = format.name;
    if (n == "Ogg") return MUS_OGG;
    if (n == "WAV") return MUS_WAV;
    if (n == "FLAC") return MUS_FLAC;
    if (n == "MP3") return MUS_MP3;
    if (n == "MIDI") return MUS_MID;
    return MUS_MOD;
}

// Puts `item` under `name`, freeing what was there only now that the new
// one is loaded (free_item: Mix_FreeChunk).
template <typename T>
void replace_named(std::unordered_map<std::string, T*>& items, const std::string& name, T* item,
                   void (*free_item)(T*)) {
    auto [it, added] = items.try_emplace(name, item);
    if (!added) {
        free_item(it->second);
        it->second = item;
    }
}

// Mix_VolumeMusic's and Mix_Volume's scale from a volume of 0–1.
int mixer_volume(double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * MIX_MAX_VOLUME)); }

}  // namespace

SoundBank::SoundBank(bool audible) {
    if (audible) {
        // The line below is all a machine without sound prints.
        silence_alsa_messages();
        audible_ = open_mixer(nullptr);
        if (!audible_)
            std::fprintf(stderr, "downstroke: no audio device (%s); sound is off\n",
                         SDL_GetError());
    }
    if (!audible_ && !open_mixer("dummy"))
        throw RenderError(std::string("audio: cannot open even the dummy driver: ") +
                          SDL_GetError());
    // Without SDL_mixer's OGG support sounds still load (Ogg sounds are
    // decoded here, ogg_decode.hpp); OGG music then fails in load_music()
    // with SDL_mixer's own reason, which is the better place to hear it.
    Mix_Init(MIX_INIT_OGG);
    Mix_AllocateChannels(kMixChannels);
}

SoundBank::~SoundBank() {
    Mix_HaltMusic();
    for (auto& [name, music] : music_) Mix_FreeMusic(music.music);
    for (auto& [name, chunk] : sounds_) Mix_FreeChunk(chunk);
    Mix_CloseAudio();
    Mix_Quit();
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void SoundBank::load(const std::string& name, const std::string& path) {
    const std::string file = read_whole("sound", path, open_file("sound", path), kMaxSoundFileBytes,
                                        "a sound file may hold");
    const SoundHeader h = checked_header(path, file);
    ChunkPtr chunk(decode_sound(path, file, h));
    if (!chunk) throw RenderError("sound " + path + ": " + Mix_GetError());
    if (int64_t(chunk->alen) > kMaxSoundDecodedBytes)  // a decoder that outgrew the header's claim
        throw RenderError("sound " + path + ": it decoded to " + std::to_string(chunk->alen >> 20) +
                          " MiB, more than the limit of " + std::to_string(kMaxSoundDecodedBytes >> 20) + " MiB");
    // Only now, with the new sound decoded, may the old one go.
    replace_named(sounds_, name, chunk.get(), Mix_FreeChunk);
    chunk.release();
}

bool SoundBank::has(const std::string& name) const { return sounds_.contains(name); }

void SoundBank::load_music(const std::string& name, const std::string& path) {
    const BoundedFile file = open_file("music", path);
    std::string error;
    const auto head = file.head(kMusicSniffBytes, error);
    if (!head) throw RenderError("music " + path + ": " + error);
    const MusicFormat* format = music_format(bytes_of(*head));
    if (!format)
        throw RenderError("music " + path + ": " +
                          (head->empty() ? std::string("it is empty")
                                         : std::string("it is not ") + kMusicFormatNames + " music"));
    const std::string allowed = std::string("allowed ") + format->bound;
    auto bytes = std::make_unique<const std::string>(read_whole("music", path, file, format->max_bytes, allowed.c_str()));
    // A WAV or an Ogg must have a sound header, though not a short one:
    // music streams, and is never decoded whole.
    SoundHeader h;
    if ((mixer_type(*format) == MUS_WAV || mixer_type(*format) == MUS_OGG) &&
        !read_sound_header(bytes_of(*bytes), h, error))
        throw RenderError("music " + path + ": " + error);
    Mix_Music* music = Mix_LoadMUSType_RW(SDL_RWFromConstMem(bytes->data(), int(bytes->size())), mixer_type(*format), 1);
    if (!music) throw RenderError("music " + path + ": " + Mix_GetError());
    auto [it, added] = music_.try_emplace(name);
    // Mix_FreeMusic stops the old music first if it is playing; its bytes go after it.
    if (!added) Mix_FreeMusic(it->second.music);
    it->second = {music, std::move(bytes)};
}

bool SoundBank::has_music(const std::string& name) const { return music_.contains(name); }

bool SoundBank::play_music(const std::string& name, bool loop, int fade_in_ms) {
    const auto it = music_.find(name);
    if (it == music_.end()) return false;
    if (audible_) Mix_FadeInMusic(it->second.music, loop ? -1 : 1, std::max(0, fade_in_ms));
    return true;
}

void SoundBank::stop_music(int fade_out_ms) {
    if (!audible_) return;
    if (fade_out_ms > 0) Mix_FadeOutMusic(fade_out_ms);
    else Mix_HaltMusic();
}

void SoundBank::set_music_volume(double v) { Mix_VolumeMusic(mixer_volume(v)); }
void SoundBank::set_sound_volume(double v) { Mix_Volume(-1, mixer_volume(v)); }

bool SoundBank::play(const std::string& name) {
    const auto it = sounds_.find(name);
    if (it == sounds_.end()) return false;
    // -1 back means every channel is busy: the sound is dropped, as promised.
    if (audible_) Mix_PlayChannel(-1, it->second, 0);
    return true;
}

}  // namespace ds::render
