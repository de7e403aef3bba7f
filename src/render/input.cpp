// SPDX-License-Identifier: MIT
#include "input.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace ds::render {

namespace {

// How far (of 32767) a stick or trigger must move before it counts as held.
// Worn sticks rest several thousand off centre, so anything lower leaves a
// character creeping on its own; this is about a quarter of the travel, near
// XInput's recommended stick deadzone (7849), and pulling a trigger a quarter
// of the way is plainly deliberate.
constexpr int kAxisDeadzone = 8000;

constexpr std::string_view kPadPrefix = "pad:";
constexpr std::string_view kMousePrefix = "mouse:";

struct MouseName {
    std::string_view name;
    Binding::Kind kind;
    int32_t code;
};

constexpr MouseName kMouseNames[] = {
    {"left", Binding::Kind::MouseButton, SDL_BUTTON_LEFT},
    {"middle", Binding::Kind::MouseButton, SDL_BUTTON_MIDDLE},
    {"right", Binding::Kind::MouseButton, SDL_BUTTON_RIGHT},
    {"x1", Binding::Kind::MouseButton, SDL_BUTTON_X1},
    {"x2", Binding::Kind::MouseButton, SDL_BUTTON_X2},
    {"wheel-up", Binding::Kind::MouseWheel, +1},
    {"wheel-down", Binding::Kind::MouseWheel, -1},
};

struct PadName {
    std::string_view name;
    Binding::Kind kind;
    int32_t code;
    int8_t sign;
};

constexpr PadName kPadNames[] = {
    {"a", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_A, 0},
    {"b", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_B, 0},
    {"x", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_X, 0},
    {"y", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_Y, 0},
    {"back", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_BACK, 0},
    {"guide", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_GUIDE, 0},
    {"start", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_START, 0},
    {"leftstick", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_LEFTSTICK, 0},
    {"rightstick", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_RIGHTSTICK, 0},
    {"leftshoulder", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_LEFTSHOULDER, 0},
    {"rightshoulder", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, 0},
    {"dpup", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_DPAD_UP, 0},
    {"dpdown", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_DPAD_DOWN, 0},
    {"dpleft", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_DPAD_LEFT, 0},
    {"dpright", Binding::Kind::PadButton, SDL_CONTROLLER_BUTTON_DPAD_RIGHT, 0},
    {"leftx-", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_LEFTX, -1},
    {"leftx+", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_LEFTX, +1},
    {"lefty-", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_LEFTY, -1},
    {"lefty+", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_LEFTY, +1},
    {"rightx-", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_RIGHTX, -1},
    {"rightx+", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_RIGHTX, +1},
    {"righty-", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_RIGHTY, -1},
    {"righty+", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_RIGHTY, +1},
    // Triggers rest at 0 and only ever go positive, so they have no "-".
    {"triggerleft+", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_TRIGGERLEFT, +1},
    {"triggerright+", Binding::Kind::PadAxis, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, +1},
};

std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool parse_pad(std::string_view rest, uint8_t action, Binding& out) {
    const std::string lower = lowercase(rest);
    for (const PadName& p : kPadNames) {
        if (p.name != lower) continue;
        out = Binding{p.kind, p.code, p.sign, action};
        return true;
    }
    return false;
}

bool parse_mouse(std::string_view rest, uint8_t action, Binding& out) {
    const std::string lower = lowercase(rest);
    for (const MouseName& m : kMouseNames) {
        if (m.name != lower) continue;
        out = Binding{m.kind, m.code, 0, action};
        return true;
    }
    return false;
}

bool is_pad_binding(const Binding& b) {
    return b.kind == Binding::Kind::PadButton || b.kind == Binding::Kind::PadAxis;
}

// The MouseState::buttons bit of an SDL button (0: none it reports).
uint8_t button_bit(uint8_t button) {
    switch (button) {
        case SDL_BUTTON_LEFT: return 1;
        case SDL_BUTTON_MIDDLE: return 2;
        case SDL_BUTTON_RIGHT: return 4;
        default: return 0;
    }
}

// A picture coordinate from a window one: floor((w − offset) / scale).
int picture_coordinate(int window, int offset, int scale) {
    const int d = window - offset;
    return d >= 0 ? d / scale : -((-d + scale - 1) / scale);
}

SDL_JoystickID instance_id(SDL_GameController* pad) {
    return SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad));
}

}  // namespace

bool parse_binding(std::string_view name, uint8_t action, Binding& out) {
    // SDL reads a C string: an embedded NUL would silently cut the name short.
    if (name.find('\0') != std::string_view::npos) return false;
    if (name.size() > kPadPrefix.size() &&
        lowercase(name.substr(0, kPadPrefix.size())) == kPadPrefix)
        return parse_pad(name.substr(kPadPrefix.size()), action, out);
    if (name.size() > kMousePrefix.size() && lowercase(name.substr(0, kMousePrefix.size())) == kMousePrefix)
        return parse_mouse(name.substr(kMousePrefix.size()), action, out);
    const SDL_Keycode key = SDL_GetKeyFromName(std::string(name).c_str());
    if (key == SDLK_UNKNOWN) return false;
    out = Binding{Binding::Kind::Key, key, 0, action};
    return true;
}

const std::vector<DefaultBinding>& default_input_map() {
    static const std::vector<DefaultBinding> map = {
        {"left", {"Left", "A", "pad:dpleft", "pad:leftx-"}},
        {"right", {"Right", "D", "pad:dpright", "pad:leftx+"}},
        {"up", {"Up", "W", "pad:dpup", "pad:lefty-"}},
        {"down", {"Down", "S", "pad:dpdown", "pad:lefty+"}},
        {"a", {"Z", "Space", "pad:a"}},
        {"b", {"X", "pad:b"}},
        {"start", {"Return", "pad:start"}},
        {"select", {"Backspace", "pad:back"}},
        {"quit", {"Escape"}},
        {"wheel-up", {"mouse:wheel-up"}},
        {"wheel-down", {"mouse:wheel-down"}},
    };
    return map;
}

InputState::~InputState() {
    // After SDL_Quit (or SDL_QuitSubSystem) SDL has already freed every
    // controller; closing them again would touch freed memory.
    if (!SDL_WasInit(SDL_INIT_GAMECONTROLLER)) return;
    for (SDL_GameController* pad : pads_) SDL_GameControllerClose(pad);
}

void InputState::set_bindings(std::vector<Binding> bindings) {
    bindings_ = std::move(bindings);
    down_.assign(bindings_.size(), 0);
}

void InputState::set_down(Binding::Kind kind, int32_t code, bool down) {
    for (size_t i = 0; i < bindings_.size(); ++i)
        if (bindings_[i].kind == kind && bindings_[i].code == code) {
            down_[i] = down;
            if (down && bindings_[i].action < kMaxActions) tapped_ |= uint64_t{1} << bindings_[i].action;
        }
}

uint64_t InputState::take_held() {
    const uint64_t bits = held() | tapped_;
    tapped_ = 0;
    return bits;
}

void InputState::handle_key(const SDL_KeyboardEvent& k) {
    // A held key repeats KEYDOWN; that is typing, not a new press.
    if (k.repeat) return;
    const bool down = k.type == SDL_KEYDOWN;
    if (down && k.keysym.sym == SDLK_F1) ++debug_toggles_;
    set_down(Binding::Kind::Key, k.keysym.sym, down);
}

void InputState::handle_axis(const SDL_ControllerAxisEvent& a) {
    for (size_t i = 0; i < bindings_.size(); ++i) {
        const Binding& b = bindings_[i];
        if (b.kind != Binding::Kind::PadAxis || b.code != a.axis) continue;
        down_[i] = b.sign * int{a.value} > kAxisDeadzone;
    }
}

void InputState::add_pad(int device_index) {
    SDL_GameController* pad = SDL_GameControllerOpen(device_index);
    if (!pad) return;  // not a controller SDL can map: nothing to read from it
    // Opening an open controller hands back the same one with one more
    // reference; drop it so the destructor's one close per pad balances.
    if (std::find(pads_.begin(), pads_.end(), pad) != pads_.end()) {
        SDL_GameControllerClose(pad);
        return;
    }
    pads_.push_back(pad);
}

void InputState::remove_pad(SDL_JoystickID id) {
    auto it = std::find_if(pads_.begin(), pads_.end(),
                           [id](SDL_GameController* p) { return instance_id(p) == id; });
    if (it != pads_.end()) {
        SDL_GameControllerClose(*it);
        pads_.erase(it);
    }
    // A pad pulled out mid-press sends no button-up: let go of what it held.
    for (size_t i = 0; i < bindings_.size(); ++i)
        if (is_pad_binding(bindings_[i])) down_[i] = 0;
}

void InputState::handle_window(const SDL_WindowEvent& w) {
    if (w.event == SDL_WINDOWEVENT_CLOSE) quit_ = true;
    // Keys released while another window has focus never reach us.
    if (w.event == SDL_WINDOWEVENT_FOCUS_LOST) {
        release_all();
        focused_ = false;
    }
    if (w.event == SDL_WINDOWEVENT_FOCUS_GAINED) focused_ = true;
    if (w.event == SDL_WINDOWEVENT_ENTER) in_window_ = true;
    if (w.event == SDL_WINDOWEVENT_LEAVE) {
        in_window_ = false;
        mouse_.inside = false;
    }
}

void InputState::set_view(const PictureView& view) {
    view_ = view;
    if (in_window_) move_mouse(window_x_, window_y_);  // the picture moved under the pointer
}

void InputState::move_mouse(int window_x, int window_y) {
    in_window_ = true;
    window_x_ = window_x;
    window_y_ = window_y;
    const int s = std::max(1, view_.scale);
    const int x = picture_coordinate(window_x, view_.x, s), y = picture_coordinate(window_y, view_.y, s);
    mouse_.inside = x >= 0 && y >= 0 && x < view_.width && y < view_.height;
    if (mouse_.inside) mouse_.x = x, mouse_.y = y;
}

MouseState InputState::take_mouse() {
    MouseState m = mouse_;
    m.buttons = static_cast<uint8_t>(m.buttons | tapped_buttons_);
    tapped_buttons_ = 0;
    return m;
}

void InputState::press_mouse(uint8_t button, bool down) {
    const uint8_t bit = button_bit(button);
    if (down) tapped_buttons_ = static_cast<uint8_t>(tapped_buttons_ | bit);
    mouse_.buttons = static_cast<uint8_t>(down ? mouse_.buttons | bit : mouse_.buttons & ~bit);
    set_down(Binding::Kind::MouseButton, button, down);
}

void InputState::handle(const SDL_Event& e) {
    switch (e.type) {
    case SDL_KEYDOWN:
    case SDL_KEYUP: handle_key(e.key); break;
    case SDL_CONTROLLERBUTTONDOWN:
    case SDL_CONTROLLERBUTTONUP:
        set_down(Binding::Kind::PadButton, e.cbutton.button,
                 e.type == SDL_CONTROLLERBUTTONDOWN);
        break;
    case SDL_CONTROLLERAXISMOTION: handle_axis(e.caxis); break;
    case SDL_CONTROLLERDEVICEADDED: add_pad(e.cdevice.which); break;
    case SDL_CONTROLLERDEVICEREMOVED: remove_pad(e.cdevice.which); break;
    case SDL_WINDOWEVENT: handle_window(e.window); break;
    case SDL_MOUSEMOTION: move_mouse(e.motion.x, e.motion.y); break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
        move_mouse(e.button.x, e.button.y);
        press_mouse(e.button.button, e.type == SDL_MOUSEBUTTONDOWN);
        break;
    case SDL_MOUSEWHEEL: {
        // A step of the wheel is a tap: its action holds for one frame.
        const int32_t dir = (e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y) > 0 ? 1 : -1;
        if (e.wheel.y != 0)
            for (const Binding& b : bindings_)
                if (b.kind == Binding::Kind::MouseWheel && b.code == dir && b.action < kMaxActions)
                    tapped_ |= uint64_t{1} << b.action;
        break;
    }
    case SDL_QUIT: quit_ = true; break;
    default: break;
    }
}

uint64_t InputState::held() const {
    uint64_t bits = 0;
    for (size_t i = 0; i < bindings_.size(); ++i) {
        // An action past the last bit has no bit to set (and shifting that
        // far is undefined).
        if (!down_[i] || bindings_[i].action >= kMaxActions) continue;
        bits |= uint64_t{1} << bindings_[i].action;
    }
    return bits;
}

int InputState::take_debug_toggles() { return std::exchange(debug_toggles_, 0); }

void InputState::release_all() {
    std::fill(down_.begin(), down_.end(), 0);
    tapped_ = 0;
    mouse_.buttons = 0;
    tapped_buttons_ = 0;
}

}  // namespace ds::render
