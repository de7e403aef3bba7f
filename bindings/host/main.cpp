// SPDX-License-Identifier: MIT
// The downstroke host: boots Guile with the native procedures registered,
// points the load paths at the compiled modules, and hands the command line
// to (downstroke host), which runs a script or the REPL.
#include <libguile.h>

#include <clocale>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include <langinfo.h>

extern "C" void ds_init_native();

namespace {

#ifdef DS_INSTALLED_HOST
// Installed, DS_SCHEME_DIR, DS_GO_DIR and DS_TEMPLATE_DIR are relative to the prefix, which is
// found from this executable's own path (PREFIX/DS_BIN_DIR/downstroke), so
// that `cmake --install --prefix P' works for any P without rebuilding.
std::string installed_dir(const char* relative) {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return relative;
    std::filesystem::path prefix = exe.parent_path();
    for (const auto& part : std::filesystem::path(DS_BIN_DIR)) {
        (void)part;
        prefix = prefix.parent_path();
    }
    return (prefix / relative).string();
}
#else
std::string installed_dir(const char* build_tree_dir) { return build_tree_dir; }
#endif

// DOWNSTROKE_SCHEME_DIR / DOWNSTROKE_GO_DIR (/ DOWNSTROKE_TEMPLATE_DIR)
// override the default paths,
// for a relocated tree.
// The C++ string is gone before any Guile call that could longjmp past it.
SCM dir_setting(const char* env, const char* fallback) {
    const char* v = std::getenv(env);
    if (v && *v) return scm_from_utf8_string(v);
    const std::string dir = installed_dir(fallback);
    return scm_from_utf8_stringn(dir.data(), dir.size());
}

// Guile encodes file names, command-line arguments and console text in the
// C locale's character set, and the C default ("C", ASCII) turns every
// non-ASCII name into "?": a folder `downstroke new ünï' made as "??n??", a
// script in such a folder not found, "≥" printed as "?". So the locale comes
// from the environment, and where that gives none or one that is not UTF-8,
// C.UTF-8 (built into glibc) takes its place: names on disk are UTF-8 bytes.
// Numbers stay in the C form (a decimal point, never a comma), as the C++
// core and the files it reads expect.
void install_locale() {
    const char* from_environment = std::setlocale(LC_ALL, "");
    const bool utf8 = from_environment && std::strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
    if (!utf8) std::setlocale(LC_ALL, "C.UTF-8");
    std::setlocale(LC_NUMERIC, "C");
}

void prepend(const char* variable, SCM dir) {
    SCM var = scm_c_lookup(variable);
    scm_variable_set_x(var, scm_cons(dir, scm_variable_ref(var)));
}

void inner_main(void*, int argc, char** argv) {
    // load-extension finds the procedures here without searching the disk.
    scm_c_register_extension("libdownstroke-guile", "ds_init_native",
                             reinterpret_cast<void (*)(void*)>(+[](void*) { ds_init_native(); }), nullptr);
    prepend("%load-path", dir_setting("DOWNSTROKE_SCHEME_DIR", DS_SCHEME_DIR));
    prepend("%load-compiled-path", dir_setting("DOWNSTROKE_GO_DIR", DS_GO_DIR));
    SCM args = SCM_EOL;
    for (int i = argc - 1; i >= 1; --i) args = scm_cons(scm_from_locale_string(argv[i]), args);
    // The templates `downstroke new' copies; DOWNSTROKE_TEMPLATE_DIR overrides.
    SCM templates = dir_setting("DOWNSTROKE_TEMPLATE_DIR", DS_TEMPLATE_DIR);
    SCM main = scm_c_public_ref("downstroke host", "main");
    SCM status = scm_call_3(main, args, scm_from_utf8_string(DS_VERSION), templates);
    std::exit(scm_is_signed_integer(status, 0, 255) ? scm_to_int(status) : 1);
}

}  // namespace

int main(int argc, char** argv) {
    install_locale();
    scm_boot_guile(argc, argv, inner_main, nullptr);
    return 0;  // not reached
}
