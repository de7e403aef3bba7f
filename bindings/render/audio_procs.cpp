// SPDX-License-Identifier: MIT
// Sounds and music as Scheme sees them: one sound bank per process, and
// what was loaded into it, so that a bank reopened on the real device has it
// all again.
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>

#include "arguments.hpp"
#include "convert.hpp"
#include "failure.hpp"
#include "registry.hpp"

#include "audio.hpp"

namespace ds::guile {

namespace {

using namespace ds::render;

std::unique_ptr<SoundBank> bank;  // one per process: there is one audio device
// What was loaded under each name, so a bank reopened on the real device
// (a window opening after the script loaded its sounds) has them all again.
std::unordered_map<std::string, std::string> sound_files;
std::unordered_map<std::string, std::string> music_files;  // likewise for music
double music_volume = 1, sound_volume = 1;                  // and the volumes set

SCM open_audio(SCM audible) {
    Failure f{"load-sound"};
    guarded(f, nullptr, [&] {
        if (!bank || (scm_is_true(audible) && !bank->audible())) {
            bank.reset();
            bank = std::make_unique<SoundBank>(scm_is_true(audible));
            for (const auto& [name, path] : sound_files) bank->load(name, path);
            for (const auto& [name, path] : music_files) bank->load_music(name, path);
            bank->set_music_volume(music_volume);
            bank->set_sound_volume(sound_volume);
        }
    });
    if (f) raise(f);
    return scm_from_bool(bank->audible());
}

// load-sound and load-music: NAME's file loaded by `load` into the bank
// (made silent if none is open yet) and remembered in `files`, so that a
// bank opened later loads it again.
SCM load_named(const char* who, SCM name, SCM path, void (SoundBank::*load)(const std::string&, const std::string&),
               std::unordered_map<std::string, std::string>& files) {
    Failure f{who};
    std::string n, p;
    guarded(f, nullptr, [&] {
        if (!symbol_arg(name, "name", n, f) || !from_scm(path, p, "file", f)) return;
        if (!bank) bank = std::make_unique<SoundBank>(false);
        (bank.get()->*load)(n, p);
        files[n] = p;
    });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM load_sound(SCM name, SCM path) { return load_named("load-sound", name, path, &SoundBank::load, sound_files); }

SCM play_sound(SCM name) {
    Failure f{"play-sound"};
    std::string n;
    bool known = false;
    guarded(f, nullptr, [&] {
        if (symbol_arg(name, "name", n, f)) known = bank && bank->play(n);
    });
    if (f) raise(f);
    return scm_from_bool(known);
}

SCM load_music(SCM name, SCM path) {
    return load_named("load-music", name, path, &SoundBank::load_music, music_files);
}

// Milliseconds of a fade: the engine has checked them (a real from 0 to
// kMaxFadeMs); here they are rounded to SDL_mixer's int.
int fade_ms(SCM ms) { return int(std::lround(scm_to_double(ms))); }

SCM play_music(SCM name, SCM loop, SCM fade_in) {
    Failure f{"play-music"};
    std::string n;
    bool known = false;
    guarded(f, nullptr, [&] {
        if (symbol_arg(name, "name", n, f)) known = bank && bank->play_music(n, scm_is_true(loop), fade_ms(fade_in));
    });
    if (f) raise(f);
    return scm_from_bool(known);
}

SCM stop_music(SCM fade_out) {
    Failure f{"stop-music"};
    guarded(f, nullptr, [&] {
        if (bank) bank->stop_music(fade_ms(fade_out));
    });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

// Volumes (checked by the engine: reals from 0 to 1), kept for a reopened bank.
SCM set_volume(SCM which, SCM volume) {
    const bool music = scm_is_eq(which, scm_from_utf8_symbol("music"));
    Failure f{music ? "music-volume-set!" : "sound-volume-set!"};
    const double v = scm_to_double(volume);
    (music ? music_volume : sound_volume) = v;
    guarded(f, nullptr, [&] {
        if (bank) music ? bank->set_music_volume(v) : bank->set_sound_volume(v);
    });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

}  // namespace

void register_audio_procedures() {
#define DS_NATIVE DS_DEFINE_NATIVE
#define DS_RENDER_NATIVE DS_DEFINE_NATIVE
#include "audio.def"
#undef DS_NATIVE
#undef DS_RENDER_NATIVE
}

}  // namespace ds::guile
