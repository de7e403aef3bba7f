// SPDX-License-Identifier: MIT
#include "registry.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "keys.hpp"

namespace ds::guile {

namespace {

// Filled in a trampoline's catch handler, raised just after it: nothing runs
// in between, so one per thread is enough (a nested native call, from a
// Scheme callback, has either raised already or not begun). Plain malloc'd
// text, as the collector need not scan thread-local storage.
thread_local const char* escaped_proc = nullptr;
thread_local char* escaped_reason = nullptr;

}  // namespace

void detail::note_escaped(const char* proc) noexcept {
    escaped_proc = proc;
    escaped_reason = copy_of_handled_reason();
}

void detail::raise_escaped() {
    Failure f{escaped_proc};
    char* reason = escaped_reason;
    escaped_reason = nullptr;
    fail_text(f, "misc-error", nullptr, reason ? reason : "unknown C++ failure (no memory to copy its text)");
    std::free(reason);
    raise(f);
}

void detail::check_one_name(const char*& registered, const char* name) {
    if (registered != nullptr && std::strcmp(registered, name) != 0)
        scm_misc_error("ds_init_native", "one C++ function registered as both ~A and ~A",
                       scm_list_2(scm_from_utf8_string(registered), scm_from_utf8_string(name)));
    registered = name;
}

void detail::define_gsubr(const char* name, int req, int opt, int rest, scm_t_subr fn, const char* doc) {
    SCM proc = scm_c_define_gsubr(name, req, opt, rest, fn);
    scm_set_procedure_property_x(proc, scm_from_utf8_symbol("documentation"), scm_from_utf8_string(doc));
    scm_c_export(name, nullptr);
}

void detail::define_gsubr(const char* name, int req, int opt, int rest, scm_t_subr fn, const WrapperDoc& doc) {
    char text[256];
    std::snprintf(text, sizeof text, "%s: native code for %s in %s, which documents it.", doc.args, doc.name,
                  doc.module);
    define_gsubr(name, req, opt, rest, fn, text);
}

}  // namespace ds::guile

// The entry point load-extension calls from (downstroke native).
extern "C" void ds_init_native() {
    using namespace ds::guile;
    init_keys();
    register_entity_procedures();
    register_tilemap_procedures();
    register_tween_procedures();
    register_frame_procedures();
    register_hash_procedures();
    register_gc_procedures();
    register_query_procedures();
    register_key_slip_procedures();
    register_constants();
    register_render_procedures();
    apply_gc_policy();
}
