// The downstroke host: boots Guile with the native procedures registered,
// points the load paths at the compiled modules, and hands the command line
// to (downstroke host), which runs a script or the REPL.
#include <libguile.h>

#include <cstdlib>

extern "C" void ds_init_native();

namespace {

// DOWNSTROKE_SCHEME_DIR / DOWNSTROKE_GO_DIR override the build-tree paths,
// for an installed or relocated tree.
const char* dir_setting(const char* env, const char* fallback) {
    const char* v = std::getenv(env);
    return v && *v ? v : fallback;
}

void prepend(const char* variable, const char* dir) {
    SCM var = scm_c_lookup(variable);
    scm_variable_set_x(var, scm_cons(scm_from_utf8_string(dir), scm_variable_ref(var)));
}

void inner_main(void*, int argc, char** argv) {
    // load-extension finds the procedures here without searching the disk.
    scm_c_register_extension("libdownstroke-guile", "ds_init_native",
                             reinterpret_cast<void (*)(void*)>(+[](void*) { ds_init_native(); }), nullptr);
    prepend("%load-path", dir_setting("DOWNSTROKE_SCHEME_DIR", DS_SCHEME_DIR));
    prepend("%load-compiled-path", dir_setting("DOWNSTROKE_GO_DIR", DS_GO_DIR));
    SCM args = SCM_EOL;
    for (int i = argc - 1; i >= 1; --i) args = scm_cons(scm_from_locale_string(argv[i]), args);
    SCM main = scm_c_public_ref("downstroke host", "main");
    SCM status = scm_call_2(main, args, scm_from_utf8_string(DS_VERSION));
    std::exit(scm_is_signed_integer(status, 0, 255) ? scm_to_int(status) : 1);
}

}  // namespace

int main(int argc, char** argv) {
    scm_boot_guile(argc, argv, inner_main, nullptr);
    return 0;  // not reached
}
