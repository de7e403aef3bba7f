#include "audio.hpp"

#include <SDL.h>
#include <SDL_mixer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <system_error>
#include <vector>

#include "constants.hpp"
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

// Why `path` cannot be decoded, or "" when it is a regular file. Asked before
// opening: opening a FIFO would block until a writer came along.
std::string not_a_sound_file(const std::string& path) {
    std::error_code ec;
    const auto st = std::filesystem::status(path, ec);
    if (st.type() == std::filesystem::file_type::not_found) return "no such file";
    if (ec) return ec.message();
    if (!std::filesystem::is_regular_file(st)) return "not a regular file";
    return "";
}

// The first bytes of a sound file (up to kSoundHeaderBytes: the whole file
// when it is no longer) and its last ones (up to kSoundTailBytes: an Ogg
// stream's length is in its last page), what read_sound_header reads.
struct SoundEnds {
    std::vector<uint8_t> head, tail;
    uint64_t size = 0;
    // The last bytes: read again only when the head is not the whole file.
    std::span<const uint8_t> last() const {
        return head.size() < size ? std::span<const uint8_t>(tail)
                                   : std::span<const uint8_t>(head).last(std::min(head.size(), kSoundTailBytes));
    }
};

// Reads the ends of the file at `path`; "" or why it could not.
std::string read_ends(const std::string& path, SoundEnds& e) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    e.size = std::filesystem::file_size(path, ec);
    if (!in || ec) return "cannot be read";
    e.head.resize(std::min<uint64_t>(e.size, kSoundHeaderBytes));
    in.read(reinterpret_cast<char*>(e.head.data()), std::streamsize(e.head.size()));
    if (e.head.size() < e.size) {
        e.tail.resize(std::min<uint64_t>(e.size, kSoundTailBytes));
        in.seekg(std::streamoff(e.size - e.tail.size()));
        in.read(reinterpret_cast<char*>(e.tail.data()), std::streamsize(e.tail.size()));
    }
    return in ? "" : "reading it failed";
}

// What SDL_mixer would allocate for the sound whose ends `e` holds, from
// its header (read before anything is decoded); "" when it is within
// kMaxSoundDecodedBytes, else why not.
std::string too_big_or_lying(const SoundEnds& e) {
    SoundHeader h;
    std::string why;
    if (!read_sound_header(e.head, e.last(), e.size, h, why)) return why;
    // Resampled to kFrequency, kOutputChannels of 16 bits: the decoded size.
    const double decoded = double(h.frames) * kFrequency / double(h.rate) * kOutputChannels * 2;
    if (decoded > double(kMaxSoundDecodedBytes))
        return std::string("its ") + h.format + " header declares " + std::to_string(h.frames) + " samples at " +
               std::to_string(h.rate) + " Hz, " + std::to_string(int64_t(decoded) >> 20) +
               " MiB decoded, more than the limit of " + std::to_string(kMaxSoundDecodedBytes >> 20) + " MiB";
    return "";
}

// Why the music file whose ends `e` holds cannot be streamed, or "": a WAV
// or an Ogg (by its magic) must have a sound header, though not a short
// one; other formats (MP3 …) are left to SDL_mixer, which names its own
// reason.
std::string bad_music_header(const SoundEnds& e) {
    auto magic = [&](const char* m) { return e.head.size() >= 4 && std::memcmp(e.head.data(), m, 4) == 0; };
    if (!magic("RIFF") && !magic("OggS")) return "";
    SoundHeader h;
    std::string why;
    return read_sound_header(e.head, e.last(), e.size, h, why) ? "" : why;
}

// The ends of the `kind` ("sound", "music") file at `path`, read once it is
// known to be a regular file of a sound's size, and passed by `check`
// (too_big_or_lying, bad_music_header); else RenderError naming the file.
SoundEnds checked_ends(const char* kind, const std::string& path, std::string (*check)(const SoundEnds&)) {
    SoundEnds e;
    std::string why = not_a_sound_file(path);
    if (why.empty()) why = read_ends(path, e);
    if (why.empty()) why = check(e);
    if (!why.empty()) throw RenderError(std::string(kind) + " " + path + ": " + why);
    return e;
}

// Puts `item` under `name`, freeing what was there only now that the new
// one is loaded (free_item: Mix_FreeChunk, Mix_FreeMusic).
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
        audible_ = open_mixer(nullptr);
        if (!audible_)
            std::fprintf(stderr, "downstroke: no audio device (%s); sound is off\n",
                         SDL_GetError());
    }
    if (!audible_ && !open_mixer("dummy"))
        throw RenderError(std::string("audio: cannot open even the dummy driver: ") +
                          SDL_GetError());
    // Without OGG support WAV still loads; an OGG file then fails in load()
    // with SDL_mixer's own reason, which is the better place to hear it.
    Mix_Init(MIX_INIT_OGG);
    Mix_AllocateChannels(kMixChannels);
}

SoundBank::~SoundBank() {
    Mix_HaltMusic();
    for (auto& [name, music] : music_) Mix_FreeMusic(music);
    for (auto& [name, chunk] : sounds_) Mix_FreeChunk(chunk);
    Mix_CloseAudio();
    Mix_Quit();
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void SoundBank::load(const std::string& name, const std::string& path) {
    const SoundEnds e = checked_ends("sound", path, too_big_or_lying);
    // The file is read once when the header read took all of it.
    ChunkPtr chunk(e.head.size() == e.size ? Mix_LoadWAV_RW(SDL_RWFromConstMem(e.head.data(), int(e.head.size())), 1)
                                           : Mix_LoadWAV(path.c_str()));
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
    checked_ends("music", path, bad_music_header);
    Mix_Music* music = Mix_LoadMUS(path.c_str());
    if (!music) throw RenderError("music " + path + ": " + Mix_GetError());
    replace_named(music_, name, music, Mix_FreeMusic);  // Mix_FreeMusic stops it first if it is playing
}

bool SoundBank::has_music(const std::string& name) const { return music_.contains(name); }

bool SoundBank::play_music(const std::string& name, bool loop, int fade_in_ms) {
    const auto it = music_.find(name);
    if (it == music_.end()) return false;
    if (audible_) Mix_FadeInMusic(it->second, loop ? -1 : 1, std::max(0, fade_in_ms));
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
