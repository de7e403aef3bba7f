// SPDX-License-Identifier: MIT
// Sounds and music by name through SDL_mixer. A sound (WAV or OGG) is
// decoded whole and played on a free channel; music (music_format.hpp) is
// read whole when loaded and decoded from those bytes as it plays, one
// track at a time. Every file is read by the bounded reader and checked
// against its bound (constants.hpp) before anything is decoded.
#pragma once
#include <memory>
#include <string>
#include <unordered_map>

struct Mix_Chunk;
typedef struct _Mix_Music Mix_Music;

namespace ds::render {

class SoundBank {
public:
    // `audible`: open the system's audio device (falling back to silence,
    // with audible() false, when there is none); otherwise SDL's "dummy"
    // driver, which decodes but plays nothing — headless runs still check
    // every file they load. Throws RenderError when not even that opens.
    explicit SoundBank(bool audible);
    ~SoundBank();
    SoundBank(const SoundBank&) = delete;
    SoundBank& operator=(const SoundBank&) = delete;

    // Decodes `path` as the sound `name`, replacing an earlier one of that
    // name. Throws RenderError naming the file when it is missing, not a
    // regular file, or cannot be decoded; the bank is then unchanged.
    void load(const std::string& name, const std::string& path);
    bool has(const std::string& name) const;
    // Starts the named sound on a free channel (a busy mixer drops it).
    // False when no sound has that name. Silent when !audible().
    bool play(const std::string& name);
    bool audible() const { return audible_; }

    // Opens `path` as the music `name` (decoded as it plays, from the file
    // read whole), replacing an earlier one of that name. Throws RenderError
    // naming the file, as load() does, for a format not recognised by its
    // bytes (music_format.hpp) or a file larger than its format's bound; a
    // WAV or OGG header is checked first, but not its length: music is never
    // decoded whole.
    void load_music(const std::string& name, const std::string& path);
    bool has_music(const std::string& name) const;
    // Plays the named music instead of any other, once or looping, fading
    // in over fade_in_ms. False when no music has that name.
    bool play_music(const std::string& name, bool loop, int fade_in_ms);
    // Stops the music, fading out over fade_out_ms (0: at once).
    void stop_music(int fade_out_ms);
    // Volumes from 0 to 1 (clamped): the music's, and every sound's.
    void set_music_volume(double v);
    void set_sound_volume(double v);

private:
    std::unordered_map<std::string, Mix_Chunk*> sounds_;
    struct Music {
        Mix_Music* music = nullptr;
        std::unique_ptr<const std::string> bytes;  // the file, which `music` reads as it plays
    };
    std::unordered_map<std::string, Music> music_;
    bool audible_ = false;
};

}  // namespace ds::render
