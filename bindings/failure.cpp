// SPDX-License-Identifier: MIT
#include "failure.hpp"

#include <cstdio>

namespace ds::guile {

void fail(Failure& f, const char* key, SCM irritants, const char* fmt, ...) {
    if (f.failed) return;  // the first failure is the one worth reporting
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(f.message, sizeof f.message, fmt, args);
    va_end(args);
    f.key = key;
    f.irritants = irritants;
    f.failed = true;
}

void fail_text(Failure& f, const char* key, const char* what, const char* text) {
    if (f.failed) return;
    size_t n = what ? static_cast<size_t>(std::snprintf(f.message, sizeof f.message, "%s: ", what)) : 0;
    for (const char* c = text; *c && n + 2 < sizeof f.message; ++c) {
        if (*c == '~') f.message[n++] = '~';
        f.message[n++] = *c;
    }
    f.message[n] = '\0';
    f.key = key;
    f.irritants = SCM_EOL;
    f.failed = true;
}

void raise(const Failure& f) {
    scm_error(scm_from_utf8_symbol(f.key), f.proc, f.message, f.irritants, SCM_BOOL_F);
}

}  // namespace ds::guile
