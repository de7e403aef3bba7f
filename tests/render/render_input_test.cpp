// Bindings by name and what InputState makes of SDL events, fed by hand: no
// window, no SDL_Init.
#include <doctest/doctest.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "input.hpp"

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
    REQUIRE(map.size() == 9);
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

}  // TEST_SUITE
