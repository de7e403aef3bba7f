// SPDX-License-Identifier: MIT
// SoundBank on SDL's dummy audio driver: it decodes every file, plays nothing,
// and needs no sound card. The WAVs are written here; the OGG is
// tests/data/sounds/tone.ogg (made by make_tone.py there).
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <SDL_mixer.h>

#include "audio.hpp"
#include "child_process.hpp"
#include "constants.hpp"
#include "render_error.hpp"
#include "sound_header.hpp"

namespace {

using ds::render::test::child_peak_kb;

namespace fs = std::filesystem;
using ds::render::RenderError;
using ds::render::SoundBank;

// A fresh directory under the system's temp folder, removed with the object.
class TempDir {
public:
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "ds-audio-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;  // best effort: a destructor must not throw
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    fs::path path_;
};

void put_le(std::string& out, uint32_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

// A 16-bit PCM mono WAV of `samples` samples of a square wave, by hand: the
// canonical 44-byte RIFF header, then the data.
void write_wav(const std::string& path, int samples, int rate = 22050) {
    const uint32_t data_bytes = static_cast<uint32_t>(samples) * 2;
    std::string w = "RIFF";
    put_le(w, 36 + data_bytes, 4);
    w += "WAVEfmt ";
    put_le(w, 16, 4);    // fmt chunk size
    put_le(w, 1, 2);     // PCM
    put_le(w, 1, 2);     // mono
    put_le(w, static_cast<uint32_t>(rate), 4);
    put_le(w, static_cast<uint32_t>(rate) * 2, 4);  // bytes per second
    put_le(w, 2, 2);     // bytes per frame
    put_le(w, 16, 2);    // bits per sample
    w += "data";
    put_le(w, data_bytes, 4);
    for (int i = 0; i < samples; ++i)
        put_le(w, static_cast<uint16_t>(static_cast<int16_t>((i / 25) % 2 ? 6000 : -6000)), 2);
    std::ofstream(path, std::ios::binary) << w;
}

// The message `load` throws, or "(no error)".
template <class Load>
std::string error_of(Load&& load) {
    try {
        load();
    } catch (const RenderError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string load_error(SoundBank& bank, const std::string& name, const std::string& path) {
    return error_of([&] { bank.load(name, path); });
}

std::string music_error(SoundBank& bank, const std::string& name, const std::string& path) {
    return error_of([&] { bank.load_music(name, path); });
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An IMA-ADPCM mono WAV of `blocks` blocks of 256 bytes (a 4-byte header,
// then 504 4-bit samples: 505 frames a block), at `rate`; the samples are
// silence. What SDL decodes it to is 505 frames a block, where a count of
// bytes over the block size gives one.
std::string ima_wav(uint32_t blocks, uint32_t rate = 44100) {
    const uint32_t data_bytes = blocks * 256;
    std::string w = "RIFF";
    put_le(w, 4 + 28 + 8 + data_bytes, 4);
    w += "WAVEfmt ";
    put_le(w, 20, 4);
    put_le(w, 0x11, 2);  // IMA ADPCM
    put_le(w, 1, 2);     // mono
    put_le(w, rate, 4);
    put_le(w, rate * 256 / 505, 4);
    put_le(w, 256, 2);   // block align
    put_le(w, 4, 2);     // bits per sample
    put_le(w, 2, 2);     // extra bytes
    put_le(w, 505, 2);   // samples per block
    w += "data";
    put_le(w, data_bytes, 4);
    w.append(data_bytes, '\0');
    return w;
}

// The Ogg page CRC (polynomial 0x04C11DB7, unreflected, from 0, the CRC
// field read as zero), bit by bit: a forged page must carry a right one.
uint32_t ogg_crc(const std::string& page) {
    uint32_t crc = 0;
    for (size_t i = 0; i < page.size(); ++i) {
        crc ^= uint32_t(uint8_t(i >= 22 && i < 26 ? 0 : page[i])) << 24;
        for (int k = 0; k < 8; ++k) crc = crc & 0x80000000u ? crc << 1 ^ 0x04C11DB7u : crc << 1;
    }
    return crc;
}

// A whole Ogg page with no packet data: end of stream, `serial`, granule
// position `granule`, a right CRC. 27 bytes and one empty segment.
std::string forged_last_page(uint32_t serial, uint64_t granule) {
    std::string p = "OggS";
    p += '\0';
    p += '\x04';  // end of stream
    put_le(p, uint32_t(granule), 4);
    put_le(p, uint32_t(granule >> 32), 4);
    put_le(p, serial, 4);
    put_le(p, 1000, 4);  // sequence number
    put_le(p, 0, 4);     // CRC, set below
    p += '\x01';        // one segment
    p += '\0';          // of no bytes
    const uint32_t crc = ogg_crc(p);
    for (int i = 0; i < 4; ++i) p[22 + i] = char(crc >> (8 * i));
    return p;
}

}  // namespace

TEST_SUITE("audio") {

TEST_CASE("a silent bank opens on the dummy driver") {
    SoundBank bank(false);
    CHECK_FALSE(bank.audible());
    CHECK_FALSE(bank.has("jump"));
    CHECK_FALSE(bank.play("unknown"));
}

TEST_CASE("a WAV loads and plays") {
    TempDir tmp;
    const std::string wav = tmp.file("blip.wav");
    write_wav(wav, 2205);
    SoundBank bank(false);
    bank.load("blip", wav);
    CHECK(bank.has("blip"));
    CHECK(bank.play("blip"));
    CHECK_FALSE(bank.has("other"));
    CHECK_FALSE(bank.play("unknown"));
}

TEST_CASE("an OGG loads and plays") {
    SoundBank bank(false);
    bank.load("tone", std::string(DS_TEST_DATA) + "/sounds/tone.ogg");
    CHECK(bank.has("tone"));
    CHECK(bank.play("tone"));
}

TEST_CASE("playing more sounds than channels drops the extra ones quietly") {
    TempDir tmp;
    write_wav(tmp.file("long.wav"), 22050);
    SoundBank bank(false);
    bank.load("long", tmp.file("long.wav"));
    for (int i = 0; i < 100; ++i) CHECK(bank.play("long"));
}

TEST_CASE("what is not a sound file is refused, naming the path") {
    TempDir tmp;
    SoundBank bank(false);

    const std::string missing = tmp.file("missing.wav");
    CHECK(contains(load_error(bank, "s", missing), missing));
    CHECK(load_error(bank, "s", missing) == "sound " + missing + ": No such file or directory");

    const std::string dir = tmp.file("folder.wav");
    fs::create_directory(dir);
    CHECK(load_error(bank, "s", dir) == "sound " + dir + ": is a directory");

    // Opening a FIFO with no writer would block: it must be refused unopened.
    const std::string fifo = tmp.file("pipe.wav");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(load_error(bank, "s", fifo) == "sound " + fifo + ": is not a regular file (a FIFO)");

    CHECK(load_error(bank, "s", "/dev/zero") == "sound /dev/zero: is not a regular file (a character device)");

    const std::string text = tmp.file("notes.wav");
    std::ofstream(text) << "these are not the samples you are looking for\n";
    CHECK(contains(load_error(bank, "s", text), text));

    const std::string empty = tmp.file("empty.wav");
    std::ofstream{empty};
    CHECK(contains(load_error(bank, "s", empty), empty));

    CHECK_FALSE(bank.has("s"));
}

// A WAV header with the given fields and `payload` bytes of samples after
// it, whatever the header claims (issue 35's lying headers).
void write_lying_wav(const std::string& path, uint32_t data_bytes, uint32_t channels, uint32_t rate,
                     uint32_t payload) {
    std::string w = "RIFF";
    put_le(w, 36 + payload, 4);
    w += "WAVEfmt ";
    put_le(w, 16, 4);
    put_le(w, 1, 2);
    put_le(w, channels, 2);
    put_le(w, rate, 4);
    put_le(w, rate * 2 * channels, 4);
    put_le(w, 2 * channels, 2);
    put_le(w, 16, 2);
    w += "data";
    put_le(w, data_bytes, 4);
    w.append(payload, '\0');
    std::ofstream(path, std::ios::binary) << w;
}

TEST_CASE("a sound whose header lies is refused from the header, naming the file, before SDL_mixer decodes it") {
    TempDir tmp;
    SoundBank bank(false);
    const std::string huge = tmp.file("huge.wav");  // 2 GB of data claimed in a 100-byte file
    write_lying_wav(huge, 0x80000000u, 1, 22050, 56);
    CHECK(load_error(bank, "s", huge) ==
          "sound " + huge + ": its WAV data chunk declares 2147483648 bytes, but the file holds 56 after it");
    const std::string choir = tmp.file("choir.wav");
    write_lying_wav(choir, 64, 60000, 22050, 64);
    CHECK(load_error(bank, "s", choir) == "sound " + choir + ": its WAV header declares 60000 channels (at most 8)");
    const std::string shrill = tmp.file("shrill.wav");
    write_lying_wav(shrill, 64, 1, 4000000000u, 64);
    CHECK(load_error(bank, "s", shrill) ==
          "sound " + shrill + ": its WAV header declares a rate of 4000000000 Hz (at most 384000)");
    // Honest but long: 20 minutes of 8 kHz mono is 19 MB of file, and 201 MiB
    // once the mixer has it at 44.1 kHz stereo.
    const std::string epic = tmp.file("epic.wav");
    write_lying_wav(epic, 8000 * 2 * 1200, 1, 8000, 8000 * 2 * 1200);
    CHECK(load_error(bank, "s", epic) ==
          "sound " + epic + ": its WAV header declares 9600000 samples at 8000 Hz, 201 MiB decoded, more than the "
                            "limit of 64 MiB");
    CHECK_FALSE(bank.has("s"));
}

TEST_CASE("an IMA-ADPCM WAV counts 505 frames a block: an honest one loads whole, a long one is refused unread") {
    TempDir tmp;
    SoundBank bank(false);
    ds::render::SoundHeader h;
    std::string why;
    const std::string small = ima_wav(10);
    REQUIRE(ds::render::read_sound_header({reinterpret_cast<const uint8_t*>(small.data()), small.size()}, h, why));
    CHECK(h.frames == 5050);
    // SDL_mixer agrees: 5050 frames at 44.1 kHz, as 2 channels of 2 bytes.
    Mix_Chunk* chunk = Mix_LoadWAV_RW(SDL_RWFromConstMem(small.data(), int(small.size())), 1);
    REQUIRE(chunk != nullptr);
    CHECK(chunk->alen == 5050 * 4);
    Mix_FreeChunk(chunk);
    std::ofstream(tmp.file("small.wav"), std::ios::binary) << small;
    bank.load("small", tmp.file("small.wav"));
    CHECK(bank.has("small"));
    // 40 000 blocks: 10 MB of file, 20.2 million frames, 77 MiB decoded; a
    // count of blocks (40 000 frames) let it through to the decoder.
    const std::string big = tmp.file("big.wav");
    std::ofstream(big, std::ios::binary) << ima_wav(40000);
    const auto start = std::chrono::steady_clock::now();
    CHECK(load_error(bank, "s", big) ==
          "sound " + big + ": its WAV header declares 20200000 samples at 44100 Hz, 77 MiB decoded, more than the "
                           "limit of 64 MiB");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
    CHECK_FALSE(bank.has("s"));
}

TEST_CASE("a WAV of an encoding not counted is refused naming it") {
    TempDir tmp;
    SoundBank bank(false);
    std::string mp3 = ima_wav(1);
    mp3[20] = 0x55;  // WAVE_FORMAT_MPEGLAYER3
    mp3[21] = 0;
    const std::string path = tmp.file("mp3.wav");
    std::ofstream(path, std::ios::binary) << mp3;
    CHECK(load_error(bank, "s", path) ==
          "sound " + path + ": its WAV encoding 85 is none the loader counts (PCM, float, A-law, µ-law, MS and IMA "
                            "ADPCM)");
}

TEST_CASE("an OGG whose last page lies is refused: a corrupt one by the check, a forged one by the capped decoder") {
    TempDir tmp;
    SoundBank bank(false);
    const std::string ogg = read_bytes(std::string(DS_TEST_DATA) + "/sounds/tone.ogg");
    // The audit's trick: a page header claiming one sample, appended without a CRC.
    std::string junk = forged_last_page(1, 1);
    junk[22] ^= 0x5a;
    const std::string appended = tmp.file("appended.ogg");
    std::ofstream(appended, std::ios::binary) << ogg << junk;
    CHECK(load_error(bank, "s", appended) ==
          "sound " + appended + ": its last Ogg page is missing or corrupt (the file is cut short or has bytes after "
                                "its end)");
    CHECK(music_error(bank, "m", appended) == "music " + appended +
                                                  ": its last Ogg page is missing or corrupt (the file is cut short "
                                                  "or has bytes after its end)");
    // A page forged whole (right CRC, the stream's serial, end of stream)
    // passes the check, claiming one sample; the decoder stops past it.
    const std::string forged = tmp.file("forged.ogg");
    std::ofstream(forged, std::ios::binary) << ogg << forged_last_page(1, 1);
    CHECK(load_error(bank, "s", forged) == "sound " + forged + ": it decodes to more than the 1 samples its last Ogg "
                                                               "page declares");
    const std::string other = tmp.file("other-stream.ogg");
    std::ofstream(other, std::ios::binary) << ogg << forged_last_page(7, 1);
    CHECK(load_error(bank, "s", other) == "sound " + other + ": its last Ogg page belongs to another stream "
                                                             "(chained Ogg files are not read)");
    CHECK_FALSE(bank.has("s"));
    // The honest file: its claim is its length.
    ds::render::SoundHeader h;
    std::string why;
    REQUIRE(ds::render::read_sound_header({reinterpret_cast<const uint8_t*>(ogg.data()), ogg.size()}, h, why));
    CHECK(h.frames == 6615);
    bank.load("tone", std::string(DS_TEST_DATA) + "/sounds/tone.ogg");
    CHECK(bank.has("tone"));
}

TEST_CASE("a truncated or corrupt OGG is refused naming the file") {
    TempDir tmp;
    SoundBank bank(false);
    std::ifstream in(std::string(DS_TEST_DATA) + "/sounds/tone.ogg", std::ios::binary);
    const std::string ogg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(ogg.size() > 200);
    const std::string cut = tmp.file("cut.ogg");  // the headers and half the audio
    std::ofstream(cut, std::ios::binary) << ogg.substr(0, ogg.size() / 2);
    CHECK(contains(load_error(bank, "s", cut), "sound " + cut + ": "));
    const std::string stub = tmp.file("stub.ogg");  // a page header and nothing more
    std::ofstream(stub, std::ios::binary) << ogg.substr(0, 20);
    CHECK(load_error(bank, "s", stub) == "sound " + stub + ": its Ogg page header is cut short");
    const std::string text = tmp.file("notes.ogg");
    std::ofstream(text) << "these are not the samples you are looking for\n";
    CHECK(load_error(bank, "s", text) == "sound " + text + ": it is not a WAV or Ogg Vorbis file");
    CHECK_FALSE(bank.has("s"));
}

TEST_CASE("a failed load leaves the earlier sound of that name; a good one replaces it") {
    TempDir tmp;
    write_wav(tmp.file("a.wav"), 1000);
    write_wav(tmp.file("b.wav"), 2000, 44100);
    const std::string bad = tmp.file("bad.wav");
    std::ofstream(bad) << "RIFF garbage";
    SoundBank bank(false);
    bank.load("s", tmp.file("a.wav"));
    CHECK(contains(load_error(bank, "s", bad), bad));
    CHECK(contains(load_error(bank, "s", tmp.file("gone.wav")), "gone.wav"));
    CHECK(bank.has("s"));
    CHECK(bank.play("s"));
    bank.load("s", tmp.file("b.wav"));
    CHECK(bank.has("s"));
    CHECK(bank.play("s"));
}

TEST_CASE("the demos' sound effects all decode") {
    SoundBank bank(false);
    const fs::path sounds = fs::path(DS_TEST_DATA) / ".." / ".." / "demo" / "sounds";
    for (const char* name : {"jump", "goal", "hit", "coin", "shot", "boom"}) {
        CAPTURE(name);
        bank.load(name, (sounds / (std::string(name) + ".wav")).string());
        CHECK(bank.play(name));
    }
}

// ---- music

// A bank that really mixes, on SDL's dummy device (no sound card needed):
// music is only started on an audible bank.
struct DummyDevice {
    DummyDevice() { setenv("SDL_AUDIODRIVER", "dummy", 1); }
    ~DummyDevice() { unsetenv("SDL_AUDIODRIVER"); }
};

TEST_CASE("music loads from OGG and WAV, plays looping or once, fades and stops") {
    DummyDevice dummy;
    TempDir tmp;
    write_wav(tmp.file("loop.wav"), 22050);
    SoundBank bank(true);
    REQUIRE(bank.audible());
    bank.load_music("theme", std::string(DS_TEST_DATA) + "/sounds/tone.ogg");
    bank.load_music("loop", tmp.file("loop.wav"));
    CHECK(bank.has_music("theme"));
    CHECK_FALSE(bank.has_music("other"));
    CHECK_FALSE(bank.play_music("other", true, 0));
    CHECK(bank.play_music("theme", true, 0));
    CHECK(Mix_PlayingMusic() == 1);
    CHECK(bank.play_music("loop", false, 200));  // in place of the theme, fading in
    CHECK(Mix_PlayingMusic() == 1);
    CHECK(Mix_FadingMusic() == MIX_FADING_IN);
    bank.stop_music(0);
    CHECK(Mix_PlayingMusic() == 0);
    CHECK(bank.play_music("theme", true, 0));
    bank.stop_music(300);
    CHECK(Mix_FadingMusic() == MIX_FADING_OUT);
    bank.stop_music(0);
}

TEST_CASE("volumes from 0 to 1 reach the mixer, clamped") {
    DummyDevice dummy;
    SoundBank bank(true);
    bank.set_music_volume(0.5);
    CHECK(Mix_VolumeMusic(-1) == MIX_MAX_VOLUME / 2);
    bank.set_music_volume(2);
    CHECK(Mix_VolumeMusic(-1) == MIX_MAX_VOLUME);
    bank.set_sound_volume(0.25);
    CHECK(Mix_Volume(0, -1) == MIX_MAX_VOLUME / 4);
    bank.set_sound_volume(-1);
    CHECK(Mix_Volume(0, -1) == 0);
}

TEST_CASE("a silent bank keeps its music but plays none") {
    SoundBank bank(false);
    bank.load_music("theme", std::string(DS_TEST_DATA) + "/sounds/tone.ogg");
    CHECK(bank.play_music("theme", true, 0));
    CHECK(Mix_PlayingMusic() == 0);
    bank.stop_music(100);
}

TEST_CASE("what is no music file is refused naming the path, and the old music stays") {
    TempDir tmp;
    SoundBank bank(false);
    const std::string missing = tmp.file("missing.ogg");
    CHECK(music_error(bank, "m", missing) == "music " + missing + ": No such file or directory");
    CHECK(music_error(bank, "m", tmp.file("")) == "music " + tmp.file("") + ": is a directory");
    std::ifstream in(std::string(DS_TEST_DATA) + "/sounds/tone.ogg", std::ios::binary);
    const std::string ogg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string stub = tmp.file("stub.ogg");
    std::ofstream(stub, std::ios::binary) << ogg.substr(0, 20);
    CHECK(music_error(bank, "m", stub) == "music " + stub + ": its Ogg page header is cut short");
    const std::string text = tmp.file("notes.txt");
    std::ofstream(text) << "not music at all, not even close";
    CHECK(contains(music_error(bank, "m", text), "music " + text + ": "));
    CHECK_FALSE(bank.has_music("m"));
    bank.load_music("m", std::string(DS_TEST_DATA) + "/sounds/tone.ogg");
    CHECK(contains(music_error(bank, "m", stub), stub));
    CHECK(bank.has_music("m"));  // the good one is still there
}

// A 31-sample "M.K." MOD: title, 31 sample headers (the first of 32 bytes
// at full volume: libmodplug refuses a module with no sample), one position
// playing pattern 0, the signature at byte 1080, that pattern (64 rows of 4
// silent channels), then the sample. 2140 bytes.
std::string tiny_mod() {
    std::string m(20, 'T');
    std::string sample(30, '\0');
    sample[23] = 16;  // length: 16 words, big-endian
    sample[25] = 64;  // volume
    m += sample;
    m.append(30 * 30, '\0');
    m += '\x01';  // song length
    m += '\x7f';  // restart byte
    m.append(128, '\0');
    m += "M.K.";
    m.append(64 * 4 * 4, '\0');
    m.append(32, '\0');
    return m;
}

// A format-0 MIDI file: one track, one note of a quarter at 96 ticks a quarter.
std::string tiny_midi() {
    const std::string track = std::string("\x00\x90\x3c\x64\x60\x80\x3c\x00\x00\xff\x2f\x00", 12);
    std::string m = "MThd";
    m += std::string("\0\0\0\x06\0\0\0\x01\0\x60", 10);
    m += "MTrk";
    m += std::string("\0\0\0", 3) + char(track.size());
    return m + track;
}

// `head` at the start of a sparse file of `size` bytes (a hole after it):
// gigabytes that take a few KB of disk.
std::string sparse_file(const TempDir& tmp, const std::string& name, const std::string& head, int64_t size) {
    const std::string path = tmp.file(name);
    std::ofstream(path, std::ios::binary) << head;
    REQUIRE(truncate(path.c_str(), size) == 0);
    return path;
}

TEST_CASE("music larger than its format's bound is refused from its size, unread, naming the file") {
    TempDir tmp;
    SoundBank bank(false);
    constexpr int64_t k21GB = int64_t(2100) << 20;
    const std::string xm_head = std::string("Extended Module: ") + std::string(60, 'x');
    struct Case {
        const char* name;
        std::string head;
        int64_t bound;
        const char* allowed;
    };
    const Case cases[] = {{"big.mod", tiny_mod(), ds::render::kMaxModuleFileBytes, "for a tracker module"},
                          {"big.xm", xm_head, ds::render::kMaxModuleFileBytes, "for a tracker module"},
                          {"big.mid", tiny_midi(), ds::render::kMaxMidiFileBytes, "for MIDI"},
                          {"big.ogg", read_bytes(std::string(DS_TEST_DATA) + "/sounds/tone.ogg"),
                           ds::render::kMaxStreamedMusicBytes, "for streamed music"}};
    for (const Case& c : cases) {
        CAPTURE(c.name);
        const std::string path = sparse_file(tmp, c.name, c.head, k21GB);
        const auto start = std::chrono::steady_clock::now();
        CHECK(music_error(bank, "m", path) == "music " + path + ": is " + std::to_string(k21GB) +
                                                  " bytes, more than the " + std::to_string(c.bound) + " bytes allowed " +
                                                  c.allowed);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
        // One byte past the bound is refused too; at the bound it is read.
        REQUIRE(truncate(path.c_str(), c.bound + 1) == 0);
        CHECK(contains(music_error(bank, "m", path), "is " + std::to_string(c.bound + 1) + " bytes, more than"));
    }
    CHECK_FALSE(bank.has_music("m"));
}

TEST_CASE("a 1 GB MIDI costs no memory: it is refused before it is read") {
    static TempDir tmp;
    static const std::string path = sparse_file(tmp, "huge.mid", tiny_midi(), int64_t(1) << 30);
    const long kb = child_peak_kb([] {
        SoundBank bank(false);
        (void)music_error(bank, "m", path);
    });
    CAPTURE(kb);
    CHECK(kb >= 0);
    CHECK(kb < 16 * 1024);
}

TEST_CASE("music is recognised by its bytes: MOD and MIDI load, anything else is refused naming the formats") {
    TempDir tmp;
    SoundBank bank(false);
    std::ofstream(tmp.file("tiny.mod"), std::ios::binary) << tiny_mod();
    bank.load_music("mod", tmp.file("tiny.mod"));
    CHECK(bank.has_music("mod"));
    std::ofstream(tmp.file("tiny.mid"), std::ios::binary) << tiny_midi();
    const std::string midi_error = music_error(bank, "midi", tmp.file("tiny.mid"));
    // SDL_mixer plays MIDI only with a sound font or Timidity patches installed.
    CHECK((midi_error == "(no error)" || contains(midi_error, "music " + tmp.file("tiny.mid") + ": ")));
    // A 15-sample MOD (no signature), or any other bytes, is not guessed at.
    std::string unsigned_mod = tiny_mod();
    unsigned_mod.replace(1080, 4, "ABCD");
    const std::string other = tmp.file("other.mod");
    std::ofstream(other, std::ios::binary) << unsigned_mod;
    CHECK(music_error(bank, "m", other) ==
          "music " + other + ": it is not Ogg Vorbis, WAV, FLAC, MP3, MIDI, MOD, XM, S3M or IT music");
    const std::string empty = tmp.file("empty.ogg");
    std::ofstream{empty};
    CHECK(music_error(bank, "m", empty) == "music " + empty + ": it is empty");
    CHECK(music_error(bank, "m", "/dev/zero") == "music /dev/zero: is not a regular file (a character device)");
    CHECK_FALSE(bank.has_music("m"));
}

}  // TEST_SUITE
