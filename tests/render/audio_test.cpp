// SoundBank on SDL's dummy audio driver: it decodes every file, plays nothing,
// and needs no sound card. The WAVs are written here; the OGG is
// tests/data/sounds/tone.ogg (made by make_tone.py there).
#include <doctest/doctest.h>
#include <sys/stat.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <SDL_mixer.h>

#include "audio.hpp"
#include "render_error.hpp"

namespace {

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

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
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
    CHECK(contains(load_error(bank, "s", missing), "no such file"));

    const std::string dir = tmp.file("folder.wav");
    fs::create_directory(dir);
    CHECK(contains(load_error(bank, "s", dir), dir));
    CHECK(contains(load_error(bank, "s", dir), "not a regular file"));

    // Opening a FIFO with no writer would block: it must be refused unopened.
    const std::string fifo = tmp.file("pipe.wav");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(contains(load_error(bank, "s", fifo), fifo));
    CHECK(contains(load_error(bank, "s", fifo), "not a regular file"));

    CHECK(contains(load_error(bank, "s", "/dev/zero"), "/dev/zero"));

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

std::string music_error(SoundBank& bank, const std::string& name, const std::string& path) {
    return error_of([&] { bank.load_music(name, path); });
}

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
    CHECK(music_error(bank, "m", missing) == "music " + missing + ": no such file");
    CHECK(music_error(bank, "m", tmp.file("")) == "music " + tmp.file("") + ": not a regular file");
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

}  // TEST_SUITE
