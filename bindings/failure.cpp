// SPDX-License-Identifier: MIT
#include "failure.hpp"

#include <cstdio>
#include <cstring>
#include <exception>

namespace ds::guile {

namespace {

char* message_space(size_t bytes) { return static_cast<char*>(scm_gc_malloc_pointerless(bytes + 1, "failure")); }

}  // namespace

void fail(Failure& f, const char* key, SCM irritants, const char* fmt, ...) {
    if (f.failed) return;  // the first failure is the one worth reporting
    va_list args, again;
    va_start(args, fmt);
    va_copy(again, args);
    const int n = std::vsnprintf(nullptr, 0, fmt, args);
    va_end(args);
    char* text = message_space(n > 0 ? static_cast<size_t>(n) : 0);
    if (n > 0) std::vsnprintf(text, static_cast<size_t>(n) + 1, fmt, again);
    else text[0] = '\0';
    va_end(again);
    f.message = text;
    f.key = key;
    f.irritants = irritants;
    f.failed = true;
}

void fail_text(Failure& f, const char* key, const char* what, const char* text) {
    if (f.failed) return;
    const size_t lead = what ? std::strlen(what) + 2 : 0;
    size_t bytes = lead;
    for (const char* c = text; *c; ++c) bytes += *c == '~' ? 2 : 1;
    char* message = message_space(bytes);
    size_t n = 0;
    if (what) {
        std::memcpy(message, what, lead - 2);
        std::memcpy(message + lead - 2, ": ", 2);
        n = lead;
    }
    for (const char* c = text; *c; ++c) {
        if (*c == '~') message[n++] = '~';
        message[n++] = *c;
    }
    message[n] = '\0';
    f.message = message;
    f.key = key;
    f.irritants = SCM_EOL;
    f.failed = true;
}

char* copy_of_handled_reason() noexcept {
    try {
        throw;
    } catch (const std::exception& e) {
        return strdup(e.what());
    } catch (...) {
        return strdup("unknown C++ failure");
    }
}

void raise(const Failure& f) {
    // scm_error would decode both texts by the locale; they are UTF-8 whatever it is.
    scm_error_scm(scm_from_utf8_symbol(f.key), f.proc ? scm_from_utf8_string(f.proc) : SCM_BOOL_F,
                  scm_from_utf8_string(f.message ? f.message : ""), f.irritants, SCM_BOOL_F);
}

}  // namespace ds::guile
