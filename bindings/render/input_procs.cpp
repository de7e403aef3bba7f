// SPDX-License-Identifier: MIT
// A window's input as Scheme sees it: the input map that binds keys and
// controller inputs to actions, and what the window's events say each frame.
#include <string>
#include <vector>

#include "arguments.hpp"
#include "convert.hpp"
#include "display.hpp"
#include "failure.hpp"
#include "registry.hpp"

#include "render/constants.hpp"

namespace ds::guile {

namespace {

using namespace ds::render;

// ((action name …) …): the actions, each with the inputs that hold it.
SCM set_input_map(SCM display, SCM map) {
    Failure f;
    Display* d = display_of(display, "make-game", f);
    std::vector<std::string> actions;
    std::vector<Binding> bindings;
    const long n = d ? scm_ilength(map) : 0;
    if (d && (n < 0 || n > kMaxActions))
        fail_arg(f, "input-map", map, "a list of at most %d (action name …)", kMaxActions);
    if (d && !f)
        guarded(f, nullptr, [&] {
            SCM p = map;
            for (long i = 0; !f && i < n; ++i, p = SCM_CDR(p)) {
                SCM entry = SCM_CAR(p);
                if (scm_ilength(entry) < 1 || !scm_is_symbol(SCM_CAR(entry))) {
                    fail_arg(f, "input-map", entry, "(action name …) with a symbol action");
                    break;
                }
                std::string action;
                symbol_arg(SCM_CAR(entry), "action", action, f);
                actions.push_back(action);
                for (SCM q = SCM_CDR(entry); scm_is_pair(q) && !f; q = SCM_CDR(q)) {
                    std::string name;
                    Binding b;
                    if (!from_scm(SCM_CAR(q), name, "input-map key", f)) break;
                    if (!parse_binding(name, static_cast<uint8_t>(i), b))
                        fail(f, "wrong-type-arg", scm_list_2(SCM_CAR(q), SCM_CAR(entry)),
                             "input-map: no key or controller input is named ~S (for ~S)");
                    else
                        bindings.push_back(b);
                }
            }
            if (f) return;
            d->actions = std::move(actions);
            d->input.set_bindings(std::move(bindings));
        });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM default_map() {
    SCM out = SCM_EOL;
    const auto& map = default_input_map();
    for (auto it = map.rbegin(); it != map.rend(); ++it) {
        SCM names = SCM_EOL;
        for (auto n = it->names.rbegin(); n != it->names.rend(); ++n) names = scm_cons(scm_from_utf8_string(*n), names);
        out = scm_cons(scm_cons(scm_from_utf8_symbol(it->action), names), out);
    }
    return out;
}

// → (held-actions quit? debug-toggles): what the window's events say now.
SCM poll_input(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    uint64_t held = 0;
    bool quit = false, focused = true;
    int toggles = 0;
    MouseState mouse;
    if (d && d->window) {
        guarded(f, nullptr, [&] { d->window->poll(d->input); });
        held = d->input.take_held();
        quit = d->input.quit_requested();
        toggles = d->input.take_debug_toggles();
        mouse = d->input.take_mouse();
        focused = d->input.focused();
        d->fullscreen = d->window->fullscreen();  // F11 may have toggled it
    }
    if (f) raise(f);
    SCM list = SCM_EOL;
    for (size_t a = d->actions.size(); a-- > 0;)
        if (held >> a & 1) list = scm_cons(scm_from_utf8_symbol(d->actions[a].c_str()), list);
    SCM pointer = SCM_BOOL_F;
    if (mouse.inside) {
        static const char* const kButtons[] = {"left", "middle", "right"};
        SCM buttons = SCM_EOL;
        for (int b = 2; b >= 0; --b)
            if (mouse.buttons >> b & 1) buttons = scm_cons(scm_from_utf8_symbol(kButtons[b]), buttons);
        pointer = scm_list_3(scm_from_int(mouse.x), scm_from_int(mouse.y), buttons);
    }
    return scm_list_5(list, scm_from_bool(quit), scm_from_int(toggles), pointer, scm_from_bool(focused));
}

}  // namespace

void register_input_procedures() {
#define DS_NATIVE DS_DEFINE_NATIVE
#define DS_RENDER_NATIVE DS_DEFINE_NATIVE
#include "input.def"
#undef DS_NATIVE
#undef DS_RENDER_NATIVE
}

}  // namespace ds::guile
