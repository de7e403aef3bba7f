// SPDX-License-Identifier: MIT
// Bindings by name and what InputState makes of SDL events, fed by hand: no
// window, no SDL_Init.
#include <doctest/doctest.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "input.hpp"
#include "window.hpp"

namespace {

using namespace ds::render;
using Kind = Binding::Kind;

// A binding no parse would produce, to see that a failed parse leaves it be.
const Binding kSentinel{Kind::PadAxis, 12345, 1, 77};

bool same(const Binding& a, const Binding& b) {
    return a.kind == b.kind && a.code == b.code && a.sign == b.sign && a.action == b.action;
}

Binding parsed(const char* name, uint8_t action) {
    Binding b = kSentinel;
    REQUIRE(parse_binding(name, action, b));
    return b;
}

std::vector<Binding> bind(std::initializer_list<std::pair<const char*, uint8_t>> names) {
    std::vector<Binding> out;
    for (auto [name, action] : names) out.push_back(parsed(name, action));
    return out;
}

SDL_Event key(Uint32 type, SDL_Keycode sym, bool repeat = false) {
    SDL_Event e{};
    e.type = type;
    e.key.type = type;
    e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
    e.key.repeat = repeat ? 1 : 0;
    e.key.keysym.sym = sym;
    return e;
}

SDL_Event axis(SDL_GameControllerAxis which, Sint16 value) {
    SDL_Event e{};
    e.type = SDL_CONTROLLERAXISMOTION;
    e.caxis.type = SDL_CONTROLLERAXISMOTION;
    e.caxis.axis = static_cast<Uint8>(which);
    e.caxis.value = value;
    return e;
}

SDL_Event button(Uint32 type, SDL_GameControllerButton which) {
    SDL_Event e{};
    e.type = type;
    e.cbutton.type = type;
    e.cbutton.button = static_cast<Uint8>(which);
    return e;
}

SDL_Event window(SDL_WindowEventID what) {
    SDL_Event e{};
    e.type = SDL_WINDOWEVENT;
    e.window.type = SDL_WINDOWEVENT;
    e.window.event = static_cast<Uint8>(what);
    return e;
}

}  // namespace

TEST_SUITE("render-input") {

TEST_CASE("keys parse by SDL's name, in any case") {
    const Binding left = parsed("Left", 3);
    CHECK(left.kind == Kind::Key);
    CHECK(left.code == SDLK_LEFT);
    CHECK(left.sign == 0);
    CHECK(left.action == 3);
    CHECK(same(parsed("left", 3), left));

    const Binding z = parsed("Z", 5);
    CHECK(z.kind == Kind::Key);
    CHECK(z.code == SDLK_z);
    CHECK(z.action == 5);

    const Binding esc = parsed("Escape", 8);
    CHECK(esc.kind == Kind::Key);
    CHECK(esc.code == SDLK_ESCAPE);
    CHECK(esc.action == 8);
}

TEST_CASE("pad buttons and axis directions parse from the table") {
    const Binding a = parsed("pad:a", 4);
    CHECK(a.kind == Kind::PadButton);
    CHECK(a.code == SDL_CONTROLLER_BUTTON_A);
    CHECK(a.sign == 0);
    CHECK(a.action == 4);

    const Binding lx = parsed("pad:leftx-", 0);
    CHECK(lx.kind == Kind::PadAxis);
    CHECK(lx.code == SDL_CONTROLLER_AXIS_LEFTX);
    CHECK(lx.sign == -1);
    CHECK(lx.action == 0);

    const Binding tr = parsed("pad:triggerright+", 9);
    CHECK(tr.kind == Kind::PadAxis);
    CHECK(tr.code == SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
    CHECK(tr.sign == 1);

    // Like key names, pad names are read in any case.
    CHECK(same(parsed("PAD:Start", 1), parsed("pad:start", 1)));
}

TEST_CASE("an unknown name is refused and leaves out alone") {
    for (const char* name : {"Nope", "pad:zz", "pad:", "", "pad:triggerleft-", "pad:leftx"}) {
        CAPTURE(name);
        Binding b = kSentinel;
        CHECK_FALSE(parse_binding(name, 1, b));
        CHECK(same(b, kSentinel));
    }
}

TEST_CASE("every name in the default map parses") {
    const auto& map = default_input_map();
    REQUIRE(map.size() == 11);
    CHECK(map.front().action == std::string("left"));
    for (const DefaultBinding& d : map) {
        for (const char* name : d.names) {
            CAPTURE(d.action);
            CAPTURE(name);
            Binding b;
            CHECK(parse_binding(name, 0, b));
        }
    }
}

TEST_CASE("a key holds its action from down to up; repeats change nothing") {
    InputState in;
    in.set_bindings(bind({{"Left", 2}}));
    CHECK(in.held() == 0);
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT));
    CHECK(in.held() == (uint64_t{1} << 2));
    in.handle(key(SDL_KEYUP, SDLK_LEFT));
    CHECK(in.held() == 0);

    // A repeat is not a press: it does not hold an action that is up.
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT, true));
    CHECK(in.held() == 0);
    in.handle(key(SDL_KEYDOWN, SDLK_RIGHT));  // unbound
    CHECK(in.held() == 0);
}

TEST_CASE("a tap inside one poll still holds its action for that poll") {
    InputState in;
    in.set_bindings(bind({{"Escape", 8}, {"Left", 0}}));
    in.handle(key(SDL_KEYDOWN, SDLK_ESCAPE));
    in.handle(key(SDL_KEYUP, SDLK_ESCAPE));
    CHECK(in.held() == 0);
    CHECK(in.take_held() == (uint64_t{1} << 8));
    CHECK(in.take_held() == 0);  // only once
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT));
    CHECK(in.take_held() == 1);
    CHECK(in.take_held() == 1);  // still down: still held
    in.handle(key(SDL_KEYUP, SDLK_LEFT));
    CHECK(in.take_held() == 0);
}

TEST_CASE("two keys on one action: letting go of one keeps it held") {
    InputState in;
    in.set_bindings(bind({{"Left", 0}, {"A", 0}, {"Right", 1}}));
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT));
    in.handle(key(SDL_KEYDOWN, SDLK_a));
    in.handle(key(SDL_KEYDOWN, SDLK_RIGHT));
    CHECK(in.held() == 0b11);
    in.handle(key(SDL_KEYUP, SDLK_LEFT));
    CHECK(in.held() == 0b11);
    in.handle(key(SDL_KEYUP, SDLK_a));
    CHECK(in.held() == 0b10);
}

TEST_CASE("an axis holds its direction only past the deadzone") {
    InputState in;
    in.set_bindings(bind({{"pad:leftx-", 0}, {"pad:leftx+", 1}, {"pad:triggerleft+", 2}}));
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTX, -20000));
    CHECK(in.held() == 0b001);
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTX, -3000));  // a stick at rest, drifting
    CHECK(in.held() == 0);
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTX, 20000));
    CHECK(in.held() == 0b010);
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTX, 32767));
    CHECK(in.held() == 0b010);
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTY, -32768));  // another axis: no binding
    CHECK(in.held() == 0b010);
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTX, 3000));
    CHECK(in.held() == 0);
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTX, -32768));
    CHECK(in.held() == 0b001);
    in.handle(axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 30000));
    CHECK(in.held() == 0b101);
}

TEST_CASE("pad buttons hold their actions") {
    InputState in;
    in.set_bindings(bind({{"pad:a", 4}, {"Z", 4}, {"pad:start", 6}}));
    in.handle(button(SDL_CONTROLLERBUTTONDOWN, SDL_CONTROLLER_BUTTON_A));
    CHECK(in.held() == (uint64_t{1} << 4));
    in.handle(button(SDL_CONTROLLERBUTTONUP, SDL_CONTROLLER_BUTTON_A));
    CHECK(in.held() == 0);
}

TEST_CASE("a controller pulled out lets go of what pads held, not of keys") {
    InputState in;
    in.set_bindings(bind({{"Left", 0}, {"pad:b", 1}, {"pad:lefty+", 2}}));
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT));
    in.handle(button(SDL_CONTROLLERBUTTONDOWN, SDL_CONTROLLER_BUTTON_B));
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTY, 30000));
    CHECK(in.held() == 0b111);
    SDL_Event e{};
    e.type = SDL_CONTROLLERDEVICEREMOVED;
    e.cdevice.type = SDL_CONTROLLERDEVICEREMOVED;
    e.cdevice.which = 42;  // never opened here: nothing to close, still released
    in.handle(e);
    CHECK(in.held() == 0b001);
}

TEST_CASE("losing focus releases everything") {
    InputState in;
    in.set_bindings(bind({{"Left", 0}, {"pad:b", 1}, {"pad:lefty+", 2}}));
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT));
    in.handle(button(SDL_CONTROLLERBUTTONDOWN, SDL_CONTROLLER_BUTTON_B));
    in.handle(axis(SDL_CONTROLLER_AXIS_LEFTY, 30000));
    CHECK(in.held() == 0b111);
    in.handle(window(SDL_WINDOWEVENT_FOCUS_LOST));
    CHECK(in.held() == 0);
    CHECK_FALSE(in.quit_requested());
}

TEST_CASE("new bindings start with nothing held") {
    InputState in;
    in.set_bindings(bind({{"Left", 0}}));
    in.handle(key(SDL_KEYDOWN, SDLK_LEFT));
    CHECK(in.held() == 1);
    in.set_bindings(bind({{"Left", 0}, {"Right", 1}}));
    CHECK(in.held() == 0);
}

TEST_CASE("F1 presses are counted for the debug overlay, bound or not") {
    InputState in;
    in.set_bindings(bind({{"F1", 7}}));
    CHECK(in.take_debug_toggles() == 0);
    in.handle(key(SDL_KEYDOWN, SDLK_F1));
    CHECK(in.held() == (uint64_t{1} << 7));
    in.handle(key(SDL_KEYDOWN, SDLK_F1, true));  // held long enough to repeat
    in.handle(key(SDL_KEYUP, SDLK_F1));
    in.handle(key(SDL_KEYDOWN, SDLK_F1));
    in.handle(key(SDL_KEYUP, SDLK_F1));
    CHECK(in.take_debug_toggles() == 2);
    CHECK(in.take_debug_toggles() == 0);
}

TEST_CASE("SDL_QUIT and a window close ask to quit") {
    InputState quit;
    CHECK_FALSE(quit.quit_requested());
    SDL_Event e{};
    e.type = SDL_QUIT;
    quit.handle(e);
    CHECK(quit.quit_requested());

    InputState close;
    close.handle(window(SDL_WINDOWEVENT_CLOSE));
    CHECK(close.quit_requested());
}

// ---- the mouse and the picture's place in the window

SDL_Event motion(int x, int y) {
    SDL_Event e{};
    e.type = SDL_MOUSEMOTION;
    e.motion.x = x;
    e.motion.y = y;
    return e;
}

SDL_Event click(Uint32 type, uint8_t b, int x, int y) {
    SDL_Event e{};
    e.type = type;
    e.button.button = b;
    e.button.x = x;
    e.button.y = y;
    return e;
}

SDL_Event wheel(int y) {
    SDL_Event e{};
    e.type = SDL_MOUSEWHEEL;
    e.wheel.y = y;
    e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
    return e;
}

TEST_CASE("the picture is scaled by the largest whole factor that fits, and centred") {
    const PictureView v = picture_view(320, 240, 1000, 700);  // ×2 = 640 × 480; ×3 would be 960 × 720
    CHECK(v.scale == 2);
    CHECK(v.x == 180);
    CHECK(v.y == 110);
    const PictureView exact = picture_view(64, 48, 320, 240);
    CHECK(exact.scale == 5);
    CHECK(exact.x == 0);
    CHECK(exact.y == 0);
    CHECK(picture_view(64, 48, 300, 200).scale == 4);
    CHECK(picture_view(64, 48, 300, 200).x == 22);
    CHECK(picture_view(64, 48, 10, 10).scale == 1);  // never below 1
}

TEST_CASE("the pointer is read in the picture's pixels, bars and scale taken out") {
    InputState in;
    in.set_view({180, 110, 2, 320, 240});
    in.handle(motion(180, 110));
    CHECK(in.mouse().inside);
    CHECK(in.mouse().x == 0);
    CHECK(in.mouse().y == 0);
    in.handle(motion(181 + 2 * 100, 111 + 2 * 50));
    CHECK(in.mouse().x == 100);
    CHECK(in.mouse().y == 50);
    in.handle(motion(179, 200));  // over the left bar
    CHECK_FALSE(in.mouse().inside);
    in.handle(motion(180 + 640, 200));  // just past the right edge
    CHECK_FALSE(in.mouse().inside);
    in.handle(motion(180 + 639, 110 + 479));
    CHECK(in.mouse().inside);
    CHECK(in.mouse().x == 319);
    CHECK(in.mouse().y == 239);
    in.handle(window(SDL_WINDOWEVENT_LEAVE));
    CHECK_FALSE(in.mouse().inside);
}

TEST_CASE("a resize moves the picture under a still pointer") {
    InputState in;
    in.set_view({0, 0, 2, 64, 48});
    in.handle(motion(40, 40));
    CHECK(in.mouse().x == 20);
    in.set_view({22, 4, 4, 64, 48});
    CHECK(in.mouse().x == 4);  // (40 − 22) / 4
    CHECK(in.mouse().y == 9);  // (40 − 4) / 4
}

TEST_CASE("mouse buttons are held, and hold the actions bound to them") {
    InputState in;
    in.set_bindings(bind({{"mouse:left", 0}, {"mouse:right", 1}, {"Z", 0}}));
    in.set_view({0, 0, 1, 100, 100});
    in.handle(click(SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, 10, 20));
    CHECK(in.mouse().buttons == 1);
    CHECK(in.mouse().x == 10);
    CHECK(in.held() == 0b01);
    in.handle(click(SDL_MOUSEBUTTONDOWN, SDL_BUTTON_RIGHT, 10, 20));
    in.handle(click(SDL_MOUSEBUTTONDOWN, SDL_BUTTON_MIDDLE, 10, 20));
    CHECK(in.mouse().buttons == 0b111);
    CHECK(in.held() == 0b11);
    in.handle(click(SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, 10, 20));
    CHECK(in.mouse().buttons == 0b110);
    CHECK(in.held() == 0b10);
    in.handle(window(SDL_WINDOWEVENT_FOCUS_LOST));
    CHECK(in.mouse().buttons == 0);
    CHECK(in.held() == 0);
    CHECK_FALSE(in.focused());
    in.handle(window(SDL_WINDOWEVENT_FOCUS_GAINED));
    CHECK(in.focused());
}

TEST_CASE("a click inside one poll shows its button for that poll") {
    InputState in;
    in.set_view({0, 0, 1, 100, 100});
    in.handle(click(SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, 5, 5));
    in.handle(click(SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, 5, 5));
    CHECK(in.mouse().buttons == 0);
    CHECK(in.take_mouse().buttons == 1);
    CHECK(in.take_mouse().buttons == 0);
}

TEST_CASE("a wheel step holds wheel-up or wheel-down for one frame") {
    InputState in;
    in.set_bindings(bind({{"mouse:wheel-up", 0}, {"mouse:wheel-down", 1}}));
    in.handle(wheel(1));
    CHECK(in.take_held() == 0b01);
    CHECK(in.take_held() == 0);
    in.handle(wheel(-2));
    CHECK(in.take_held() == 0b10);
    CHECK(in.held() == 0);
}

TEST_CASE("mouse names parse; unknown ones are refused") {
    CHECK(same(parsed("mouse:left", 3), Binding{Kind::MouseButton, SDL_BUTTON_LEFT, 0, 3}));
    CHECK(same(parsed("MOUSE:Right", 3), Binding{Kind::MouseButton, SDL_BUTTON_RIGHT, 0, 3}));
    CHECK(same(parsed("mouse:wheel-down", 2), Binding{Kind::MouseWheel, -1, 0, 2}));
    Binding b = kSentinel;
    CHECK_FALSE(parse_binding("mouse:fourth", 1, b));
    CHECK_FALSE(parse_binding("mouse:", 1, b));
    CHECK(same(b, kSentinel));
}

}  // TEST_SUITE
