// SPDX-License-Identifier: MIT
#include "common/guile_boot.hpp"

#include <libguile.h>

#include <cstdlib>

extern "C" void ds_init_native();

namespace bench {

namespace {

void prepend(const char* variable, const char* dir) {
    SCM var = scm_c_lookup(variable);
    scm_variable_set_x(var, scm_cons(scm_from_utf8_string(dir), scm_variable_ref(var)));
}

void* init_guile(void*) {
    scm_c_register_extension("libdownstroke-guile", "ds_init_native",
                             reinterpret_cast<void (*)(void*)>(+[](void*) { ds_init_native(); }), nullptr);
    prepend("%load-path", DS_SCHEME_DIR);
    prepend("%load-compiled-path", DS_GO_DIR);
    prepend("%load-path", DS_BENCH_SCHEME_DIR);
    prepend("%load-compiled-path", DS_BENCH_GO_DIR);
    return nullptr;
}

}  // namespace

void ensure_guile() {
    static bool booted = false;
    if (booted) return;
    setenv("GUILE_AUTO_COMPILE", "0", 0);
    scm_with_guile(init_guile, nullptr);
    booted = true;
}

std::string guile_version() {
    ensure_guile();
    std::string v;
    scm_with_guile(
        +[](void* out) -> void* {
            char* text = scm_to_utf8_string(scm_version());
            *static_cast<std::string*>(out) = text;
            free(text);
            return nullptr;
        },
        &v);
    return v;
}

std::string error_text(SCM key, SCM args) {
    char* text = scm_to_utf8_string(scm_object_to_string(scm_cons(key, args), SCM_UNDEFINED));
    std::string out = text;
    free(text);
    return out;
}

}  // namespace bench
