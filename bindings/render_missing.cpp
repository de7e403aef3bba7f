// Stands in for render_procs.cpp in a build without SDL2: the same names,
// each refusing with a message that says what to install.
#include <iterator>
#include <utility>

#include "failure.hpp"
#include "registry.hpp"

namespace ds::guile {

namespace {

// render_procs.cpp's procedures; each stand-in takes any arguments.
constexpr const char* kStandIns[] = {
    "%make-display",      "%display-open-window!",    "%display-close-window!", "%display-draw!",
    "%display-stats",     "%display-save-png",        "%display-pixel",         "%display-clear-commands!",
    "%draw-rect!",        "%draw-line!",              "%draw-sprite!",          "%draw-text!",
    "%display-set-input-map!", "%display-poll!",      "%open-audio!",           "%load-sound",
    "%play-sound",        "%note-pushed-pairs!",      "%load-music",            "%play-music",
    "%stop-music",        "%set-volume!",             "%display-set-fullscreen!", "%display-fullscreen?",
    "%display-refresh-rate", "%display-vsync?",   "%display-compare-png",   "%named-colors"};

// One function per name (I), as each registered function has one name.
template <size_t I>
SCM missing(SCM) {
    Failure f{"downstroke"};
    fail_text(f, "misc-error", nullptr,
              "this build has no renderer: install libsdl2-dev libsdl2-image-dev libsdl2-mixer-dev and rebuild");
    raise(f);
}

template <size_t... I>
void define_stand_ins(std::index_sequence<I...>) {
    (define_procedure<0, 0, 1, missing<I>>(kStandIns[I], "Not in this build: it has no renderer (SDL2)."), ...);
}

SCM renderer_p() { return SCM_BOOL_F; }
SCM default_input_map() { return SCM_EOL; }

}  // namespace

void register_render_procedures() {
    define_procedure<0, 0, 0, renderer_p>("%renderer?", WrapperDoc{"()", "renderer-available?", "(downstroke render)"});
    define_procedure<0, 0, 0, default_input_map>("%default-input-map",
        WrapperDoc{"()", "default-input-map", "(downstroke render)"});
    define_stand_ins(std::make_index_sequence<std::size(kStandIns)>());
}

}  // namespace ds::guile
