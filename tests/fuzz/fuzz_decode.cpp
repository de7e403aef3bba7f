// SPDX-License-Identifier: MIT
// Differential libFuzzer target (issue 45): every "refuse it before
// decoding" check against the decoder it protects. The bytes go to the
// image header reader and the sound header reader; when one accepts them
// with a claim small enough to decode here (kFuzzDecodeBytes), the same
// bytes are decoded as the loaders decode them — SDL_image for images,
// SDL's WAV decoder and SDL_mixer for WAV sounds, ogg_decode for Ogg — and
// what comes out must be what was claimed: an image of exactly the claimed
// size, a sound of no more frames, channels and bytes than claimed. A
// decoder that yields more is a check that can be walked past: abort.
#include <SDL.h>
#include <SDL_image.h>
#include <SDL_mixer.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

#include "render/image_header.hpp"
#include "render/music_format.hpp"
#include "render/ogg_decode.hpp"
#include "render/sound_header.hpp"

namespace {

// Claims above this are not decoded: the check's bound is far larger, and
// decoding it would take the run's memory and time for nothing the small
// inputs (max_len 4096) could not show.
constexpr double kFuzzDecodeBytes = 16 << 20;
// The mixer's format, as the sound bank opens it (audio.cpp).
constexpr int kFrequency = 44100, kChannels = 2;

// DS_FUZZ_SHOW=1: each claim and what the decoder made of it, on stderr.
const bool kShow = std::getenv("DS_FUZZ_SHOW") != nullptr;

void show(const char* what, double claimed, double got) {
    if (kShow) std::fprintf(stderr, "fuzz_decode: %s: claimed %.0f, decoded %.0f\n", what, claimed, got);
}

[[noreturn]] void finding(const char* what, double claimed, double got) {
    std::fprintf(stderr, "fuzz_decode: %s: the check claimed %.0f, the decoder made %.0f\n", what, claimed, got);
    std::abort();
}

void check_image(std::span<const uint8_t> b) {
    ds::render::ImageHeader h;
    std::string why;
    if (!ds::render::read_image_header(b, h, why)) {
        if (why.empty()) std::abort();  // every refusal says why
        return;
    }
    if (double(h.width) * double(h.height) * 4 > kFuzzDecodeBytes) return;
    // The loader refuses GIF (tile_art.cpp): SDL_image's decoder writes past
    // its buffers on hostile LZW data, which this target found; its size
    // claim was exact on every file that did not crash it.
    if (std::string_view(h.format) == "GIF") return;
    const char* type = std::string_view(h.format) == "JPEG" ? "JPG" : h.format;  // as tile_art.cpp asks
    SDL_Surface* s = IMG_LoadTyped_RW(SDL_RWFromConstMem(b.data(), int(b.size())), 1, type);
    if (!s) return;  // refused by the decoder: the loader names the file
    const int w = s->w, hgt = s->h;
    SDL_FreeSurface(s);
    show("image pixels", double(h.width) * double(h.height), double(w) * hgt);
    if (w != h.width) finding("image width", double(h.width), w);
    if (hgt != h.height) finding("image height", double(h.height), hgt);
}

void check_sound(std::span<const uint8_t> b) {
    ds::render::SoundHeader h;
    std::string why;
    if (!ds::render::read_sound_header(b, h, why)) {
        if (why.empty()) std::abort();
        return;
    }
    const double native = double(h.frames) * double(h.channels) * double(h.decoded_sample_bytes);
    // The mixer's conversion may round a frame or two up at each end.
    const double mixed = (double(h.frames) * kFrequency / double(h.rate) + 4) * kChannels * 2;
    if (native > kFuzzDecodeBytes || mixed > kFuzzDecodeBytes) return;
    if (std::string_view(h.format) == "OGG") {
        ds::render::DecodedOgg d;
        if (!ds::render::decode_ogg(b, h.channels, h.rate, h.frames, d, why)) return;
        show("Ogg samples", double(h.frames) * double(h.channels), double(d.samples.size()));
        if (double(d.samples.size()) > double(h.frames) * double(h.channels))
            finding("Ogg samples", double(h.frames) * double(h.channels), double(d.samples.size()));
        return;
    }
    // A WAV: SDL's decoder at the file's own rate, then SDL_mixer's chunk.
    SDL_AudioSpec spec;
    Uint8* buf = nullptr;
    Uint32 len = 0;
    if (SDL_LoadWAV_RW(SDL_RWFromConstMem(b.data(), int(b.size())), 1, &spec, &buf, &len)) {
        const int channels = spec.channels;
        SDL_FreeWAV(buf);
        show("WAV bytes decoded", native, len);
        if (channels != h.channels) finding("WAV channels", double(h.channels), channels);
        if (double(len) > native) finding("WAV bytes decoded", native, len);
    }
    if (Mix_Chunk* c = Mix_LoadWAV_RW(SDL_RWFromConstMem(b.data(), int(b.size())), 1)) {
        const double alen = c->alen;
        Mix_FreeChunk(c);
        show("WAV bytes mixed", mixed, alen);
        if (alen > mixed) finding("WAV bytes mixed", mixed, alen);
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    setenv("SDL_AUDIODRIVER", "dummy", 1);
    if (SDL_Init(SDL_INIT_AUDIO) != 0 || Mix_OpenAudio(kFrequency, MIX_DEFAULT_FORMAT, kChannels, 1024) != 0) {
        std::fprintf(stderr, "fuzz_decode: no dummy audio: %s\n", SDL_GetError());
        std::exit(1);
    }
    IMG_Init(IMG_INIT_PNG | IMG_INIT_JPG);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::span<const uint8_t> b(data, size);
    check_image(b);
    check_sound(b);
    // The music sniffer reads no further than its window, whatever the bytes.
    (void)ds::render::music_format(b.first(std::min(b.size(), ds::render::kMusicSniffBytes)));
    return 0;
}
