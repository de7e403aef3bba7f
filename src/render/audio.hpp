// Sounds by name through SDL_mixer: WAV and OGG (anything SDL_mixer decodes).
#pragma once
#include <string>
#include <unordered_map>

struct Mix_Chunk;

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

private:
    std::unordered_map<std::string, Mix_Chunk*> sounds_;
    bool audible_ = false;
};

}  // namespace ds::render
