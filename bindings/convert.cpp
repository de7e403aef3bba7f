// SPDX-License-Identifier: MIT
#include "convert.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace ds::guile {

void fail_arg(Failure& f, Arg a, SCM v, const char* what, ...) {
    if (f) return;  // the first failure is the one reported
    char expected[192];
    va_list args;
    va_start(args, what);
    std::vsnprintf(expected, sizeof expected, what, args);
    va_end(args);
    if (a.name)
        fail(f, "wrong-type-arg", scm_list_1(v), "%s: expected %s, got ~S", a.name, expected);
    else
        fail(f, "wrong-type-arg", scm_list_2(scm_from_int(a.position), v), "argument ~S: expected %s, got ~S", expected);
}

bool from_scm(SCM v, int& out, Arg a, Failure& f, int lo, int hi, const char* what) {
    if (scm_is_signed_integer(v, lo, hi)) {
        out = scm_to_int(v);
        return true;
    }
    if (what) fail_arg(f, a, v, "%s", what);
    else fail_arg(f, a, v, "an exact integer from %d to %d", lo, hi);
    return false;
}

bool from_scm(SCM v, uint32_t& out, Arg a, Failure& f, const char* what) {
    if (scm_is_unsigned_integer(v, 0, UINT32_MAX)) {
        out = scm_to_uint32(v);
        return true;
    }
    fail_arg(f, a, v, "%s", what);
    return false;
}

bool from_scm(SCM v, std::string& out, Arg a, Failure& f) {
    if (!scm_is_string(v)) {
        fail_arg(f, a, v, "a string");
        return false;
    }
    // Freed even if the copy throws (no Guile call can longjmp in between).
    const std::unique_ptr<char, decltype(&std::free)> text(scm_to_utf8_string(v), &std::free);
    out.assign(text.get());
    return true;
}

}  // namespace ds::guile
