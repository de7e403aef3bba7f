// Stands in for render_procs.cpp in a build without SDL2: the same names,
// each refusing with a message that says what to install.
#include "failure.hpp"
#include "registry.hpp"

namespace ds::guile {

namespace {

SCM missing(SCM) {
    Failure f{.proc = "downstroke"};
    fail_text(f, "misc-error", nullptr,
              "this build has no renderer: install libsdl2-dev libsdl2-image-dev libsdl2-mixer-dev and rebuild");
    raise(f);
}

}  // namespace

void register_render_procedures() {
    define_procedure("%renderer?", 0, 0, 0, (Subr) + [] { return SCM_BOOL_F; },
                     "(): whether this build has the renderer (SDL2).");
    define_procedure("%default-input-map", 0, 0, 0, (Subr) + [] { return SCM_EOL; },
                     "(): no inputs without the renderer.");
    const struct {
        const char* name;
        int req;
    } procs[] = {{"%make-display", 2},  {"%display-open-window!", 3}, {"%display-close-window!", 1},
                 {"%display-draw!", 7}, {"%display-stats", 1},        {"%display-save-png", 2},
                 {"%display-pixel", 3}, {"%display-clear-commands!", 1}, {"%draw-rect!", 8},
                 {"%draw-line!", 7},    {"%draw-sprite!", 5},         {"%draw-text!", 7},
                 {"%display-set-input-map!", 2}, {"%display-poll!", 1}, {"%open-audio!", 1},
                 {"%load-sound", 2},    {"%play-sound", 1},           {"%note-pushed-pairs!", 1}};
    for (const auto& p : procs)
        define_procedure(p.name, 0, 0, 1, (Subr)missing, "Not in this build: it has no renderer (SDL2).");
}

}  // namespace ds::guile
