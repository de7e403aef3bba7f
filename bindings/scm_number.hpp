// SPDX-License-Identifier: MIT
// Scheme reals ⇄ ds::Num. Fixnums and flonums take a fast path; exactness
// survives the round trip (semantics §1).
#pragma once
#include <libguile.h>

#include <cmath>

#include "number.hpp"

namespace ds::guile {

// OutOfRange: an exact number too large for a double (a bignum such as
// (expt 10 400)), which is finite, so "expected a finite number" would
// puzzle; its message says the range instead (kDoubleRange).
enum class NumCheck { Ok, NotReal, NotFinite, OutOfRange };

// The range an exact number must lie in, as messages state it: the core
// computes in doubles, whose largest is about 1.8e308.
inline constexpr const char* kDoubleRange = "between -1.8e308 and 1.8e308 (a double's range)";

// Exact integers stay exact at any size (beyond 2^53 they are rounded to the
// nearest double, as the core computes in double: semantics §1); exact non-integer
// rationals and flonums become flonums. Non-reals and NaN/±inf are refused,
// and exact numbers past a double's range.
inline NumCheck num_from_scm(SCM v, Num& out) {
    if (SCM_I_INUMP(v)) {
        out = Num::integer(static_cast<double>(SCM_I_INUM(v)));
        return NumCheck::Ok;
    }
    double d;
    if (SCM_REALP(v)) d = SCM_REAL_VALUE(v);
    else if (scm_is_real(v)) d = scm_to_double(v);
    else return NumCheck::NotReal;
    if (!std::isfinite(d)) return SCM_REALP(v) ? NumCheck::NotFinite : NumCheck::OutOfRange;
    out = {d, scm_is_exact_integer(v) != 0};
    return NumCheck::Ok;
}

// Exact results become exact integers (bignums past int64), the rest flonums.
inline SCM num_to_scm(Num n) {
    if (!n.exact) return scm_from_double(n.v);
    if (std::fabs(n.v) < 9.2e18) return scm_from_int64(static_cast<int64_t>(n.v));
    return scm_inexact_to_exact(scm_from_double(n.v));
}

}  // namespace ds::guile
