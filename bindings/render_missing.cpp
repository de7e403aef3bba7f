// SPDX-License-Identifier: MIT
// Stands in for the renderer's procedures (render/) in a build without SDL2:
// the same names, from the same tables (render/natives.def), each refusing
// with a message that says what to install.
#include <iterator>
#include <utility>

#include "failure.hpp"
#include "registry.hpp"

namespace ds::guile {

namespace {

// The procedures that need the renderer; each stand-in takes any arguments.
constexpr const char* kStandIns[] = {
#define DS_NATIVE(...)
#define DS_RENDER_NATIVE(name, ...) name,
#include "render/natives.def"
#undef DS_NATIVE
#undef DS_RENDER_NATIVE
};

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

// The no-renderer versions of the tables' DS_NATIVE rows.
SCM renderer_p() { return SCM_BOOL_F; }
SCM default_map() { return SCM_EOL; }

}  // namespace

void register_render_procedures() {
#define DS_NATIVE DS_DEFINE_NATIVE
#define DS_RENDER_NATIVE(...)
#include "render/natives.def"
#undef DS_NATIVE
#undef DS_RENDER_NATIVE
    define_stand_ins(std::make_index_sequence<std::size(kStandIns)>());
}

}  // namespace ds::guile
