// SPDX-License-Identifier: MIT
// The display's Scheme type, and registering the renderer's procedures.
#include "display.hpp"

#include "arguments.hpp"
#include "registry.hpp"

namespace ds::guile {

namespace {

SCM display_type = SCM_BOOL_F;

void finalize_display(SCM obj) {
    delete static_cast<Display*>(scm_foreign_object_ref(obj, 0));
    scm_foreign_object_set_x(obj, 0, nullptr);
}

}  // namespace

Display* display_of(SCM obj, const char* proc, Failure& f) {
    f.proc = proc;
    if (SCM_IS_A_P(obj, display_type)) {
        if (auto* d = static_cast<Display*>(scm_foreign_object_ref(obj, 0))) return d;
    }
    fail(f, "wrong-type-arg", scm_list_1(obj), "expected a display, got ~S");
    return nullptr;
}

render::Canvas& canvas_of(Display& d) {
    if (!d.canvas) d.canvas = std::make_unique<render::Canvas>(d.width, d.height);
    return *d.canvas;
}

SCM wrap_display(Display* d) { return scm_make_foreign_object_1(display_type, d); }

void register_render_procedures() {
    display_type = scm_make_foreign_object_type(scm_from_utf8_symbol("display"),
                                                scm_list_1(scm_from_utf8_symbol("data")), finalize_display);
    scm_permanent_object(display_type);
    register_render_arguments();
    register_display_procedures();
    register_draw_procedures();
    register_input_procedures();
    register_audio_procedures();
}

}  // namespace ds::guile
