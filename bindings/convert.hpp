// SPDX-License-Identifier: MIT
// Argument conversions for the native procedures. Each takes the value,
// where it stands in the call (Arg) and the procedure's Failure, and either
// sets `out` and returns true, or records
//     "<name>: expected <what>, got <value>"   (or "argument <n>: …")
// as a wrong-type-arg and returns false. None raises and none throws past
// its own cleanup: the caller raises once its C++ objects are gone.
#pragma once
#include <libguile.h>

#include <cstdint>
#include <string>

#include "failure.hpp"
#include "scm_number.hpp"

namespace ds::guile {

// An argument as the message names it: by name ("x", "#:sprite", "camera
// x"), or by position from 1 for a procedure whose arguments are all alike.
struct Arg {
    const char* name = nullptr;
    int position = 0;
    constexpr Arg(const char* n) : name(n) {}
    constexpr Arg(int p) : position(p) {}
};

// Records "<arg>: expected <what>, got ~S" (irritant v; by position
// "argument ~S: expected <what>, got ~S", irritants the position and v).
// `what` is a printf format for its own arguments; it must hold no ~.
void fail_arg(Failure& f, Arg a, SCM v, const char* what, ...) __attribute__((format(printf, 4, 5)));

// A finite real number: fixnums, flonums, bignums and exact rationals (as
// the nearest double); NaN, ±inf and non-reals are refused. Inline, as
// aabb-overlap? converts eight per call.
inline bool from_scm(SCM v, double& out, Arg a, Failure& f, const char* what = "a finite real number") {
    Num n;
    const NumCheck c = num_from_scm(v, n);
    if (c == NumCheck::Ok) [[likely]] {
        out = n.v;
        return true;
    }
    if (c == NumCheck::OutOfRange) fail_arg(f, a, v, "%s %s", what, kDoubleRange);
    else fail_arg(f, a, v, "%s", what);
    return false;
}
// An exact integer in [lo, hi]; `what` (say "a positive exact integer")
// replaces the default "an exact integer from lo to hi".
bool from_scm(SCM v, int& out, Arg a, Failure& f, int lo, int hi, const char* what = nullptr);
// An exact integer in [0, 2^32).
bool from_scm(SCM v, uint32_t& out, Arg a, Failure& f, const char* what = "an exact integer from 0 to 4294967295");
// A string, as UTF-8.
bool from_scm(SCM v, std::string& out, Arg a, Failure& f);

}  // namespace ds::guile
