// SPDX-License-Identifier: MIT
// Keyboard, game controllers and the mouse → the actions a game reads (left,
// right, …), and where the pointer is in the game's picture.
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
    enum class Kind : uint8_t { Key, PadButton, PadAxis, MouseButton, MouseWheel };
    Kind kind = Kind::Key;
    // SDL_Keycode, SDL_GameControllerButton, SDL_GameControllerAxis, an
    // SDL_BUTTON_* number, or for the wheel +1 (up) and -1 (down).
    int32_t code = 0;
    int8_t sign = 0;   // PadAxis: -1 holds the action below −deadzone, +1 above +deadzone
    uint8_t action = 0;
};

// A binding from its name: a key as SDL_GetKeyFromName spells it ("Left",
// "Z", "Space", "Return", "Escape", "F1" …, any case), or a controller input
// "pad:a" "pad:b" "pad:x" "pad:y" "pad:back" "pad:start" "pad:guide"
// "pad:leftshoulder" "pad:rightshoulder" "pad:leftstick" "pad:rightstick"
// "pad:dpup" "pad:dpdown" "pad:dpleft" "pad:dpright", or an axis direction
// "pad:leftx-" "pad:leftx+" "pad:lefty-" "pad:lefty+" (likewise rightx,
// righty, and "pad:triggerleft+" "pad:triggerright+"), or a mouse input
// "mouse:left" "mouse:middle" "mouse:right" "mouse:x1" "mouse:x2" and
// "mouse:wheel-up" "mouse:wheel-down" (a wheel step holds its action for one
// frame). False, `out` untouched, for a name it does not know.
bool parse_binding(std::string_view name, uint8_t action, Binding& out);

// The default map: action name → the names bound to it.
struct DefaultBinding {
    const char* action;
    std::vector<const char*> names;
};
const std::vector<DefaultBinding>& default_input_map();

// Where the game's picture is in the window: its top-left corner and whole
// scale, and its size in picture pixels (Window::view).
struct PictureView {
    int x = 0, y = 0, scale = 1;
    int width = 0, height = 0;
};

// The pointer over the picture, in picture pixels (the window's scale and
// bars taken out), and the buttons held: bit 0 left, 1 middle, 2 right.
struct MouseState {
    bool inside = false;  // over the picture (not over a bar, not outside the window)
    int x = 0, y = 0;
    uint8_t buttons = 0;
};

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
    // Where the picture is now: mouse positions are read through it.
    void set_view(const PictureView& view);
    const MouseState& mouse() const { return mouse_; }
    // mouse(), with every button pressed since the last call counted as
    // held: a click inside one poll still shows for a frame, as take_held()
    // keeps a tap's action.
    MouseState take_mouse();
    // Whether the window has the keyboard focus (it starts focused).
    bool focused() const { return focused_; }
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
    void move_mouse(int window_x, int window_y);
    void press_mouse(uint8_t button, bool down);
    void add_pad(int device_index);
    void remove_pad(SDL_JoystickID id);

    std::vector<Binding> bindings_;
    std::vector<uint8_t> down_;  // per binding: its input is down
    std::vector<SDL_GameController*> pads_;
    bool quit_ = false;
    int debug_toggles_ = 0;
    uint64_t tapped_ = 0;  // actions that went down since take_held()
    PictureView view_;
    MouseState mouse_;
    uint8_t tapped_buttons_ = 0;  // buttons that went down since take_mouse()
    bool in_window_ = false;  // the pointer is over the window (enter/leave events)
    int window_x_ = 0, window_y_ = 0;  // where it was last, in window pixels
    bool focused_ = true;
};

}  // namespace ds::render
