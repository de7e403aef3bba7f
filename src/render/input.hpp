// Keyboard and game controllers → the actions a game reads (left, right, …).
// Actions are small numbers (a game's action names are kept by the caller,
// up to 64 of them); physical inputs are bound to them by name.
#pragma once
#include <SDL.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ds::render {

constexpr int kMaxActions = 64;  // one bit each in a uint64_t

struct Binding {
    enum class Kind : uint8_t { Key, PadButton, PadAxis };
    Kind kind = Kind::Key;
    int32_t code = 0;  // SDL_Keycode, SDL_GameControllerButton or SDL_GameControllerAxis
    int8_t sign = 0;   // PadAxis: -1 holds the action below −deadzone, +1 above +deadzone
    uint8_t action = 0;
};

// A binding from its name: a key as SDL_GetKeyFromName spells it ("Left",
// "Z", "Space", "Return", "Escape", "F1" …, any case), or a controller input
// "pad:a" "pad:b" "pad:x" "pad:y" "pad:back" "pad:start" "pad:guide"
// "pad:leftshoulder" "pad:rightshoulder" "pad:leftstick" "pad:rightstick"
// "pad:dpup" "pad:dpdown" "pad:dpleft" "pad:dpright", or an axis direction
// "pad:leftx-" "pad:leftx+" "pad:lefty-" "pad:lefty+" (likewise rightx,
// righty, and "pad:triggerleft+" "pad:triggerright+"). False, `out`
// untouched, for a name it does not know.
bool parse_binding(std::string_view name, uint8_t action, Binding& out);

// The default map: action name → the names bound to it.
struct DefaultBinding {
    const char* action;
    std::vector<const char*> names;
};
const std::vector<DefaultBinding>& default_input_map();

// What is held, fed from SDL events. Controllers are opened as they are
// plugged in (SDL_CONTROLLERDEVICEADDED, also sent for those present at
// start-up) and closed when removed.
class InputState {
public:
    InputState() = default;
    ~InputState();
    InputState(const InputState&) = delete;
    InputState& operator=(const InputState&) = delete;

    void set_bindings(std::vector<Binding> bindings);
    // Feeds one event. Key repeats are ignored.
    void handle(const SDL_Event& e);
    // Bit a set: action a is held by at least one of its inputs.
    uint64_t held() const;
    // held(), plus every action that went down since the last call even if
    // it is up again: a tap shorter than one frame (both events in one poll)
    // still holds its action for a frame instead of vanishing.
    uint64_t take_held();
    // The window's close button (SDL_QUIT or a window close event) was used.
    bool quit_requested() const { return quit_; }
    // How many times F1 went down since the last call (the debug overlay's toggle).
    int take_debug_toggles();
    // Releases everything (the window lost focus: no key stays stuck down).
    void release_all();

private:
    // Marks every binding of this kind and code as down or up.
    void set_down(Binding::Kind kind, int32_t code, bool down);
    void handle_key(const SDL_KeyboardEvent& k);
    void handle_axis(const SDL_ControllerAxisEvent& a);
    void handle_window(const SDL_WindowEvent& w);
    void add_pad(int device_index);
    void remove_pad(SDL_JoystickID id);

    std::vector<Binding> bindings_;
    std::vector<uint8_t> down_;  // per binding: its input is down
    std::vector<SDL_GameController*> pads_;
    bool quit_ = false;
    int debug_toggles_ = 0;
    uint64_t tapped_ = 0;  // actions that went down since take_held()
};

}  // namespace ds::render
