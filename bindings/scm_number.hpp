// Scheme reals ⇄ ds::Num. Fixnums and flonums take a fast path; exactness
// survives the round trip (semantics §1).
#pragma once
#include <libguile.h>

#include <cmath>

#include "number.hpp"

namespace ds::guile {

enum class NumCheck { Ok, NotReal, NotFinite };

// Exact integers stay exact at any size (beyond 2^53 they are rounded to the
// nearest double, as the core computes in double: semantics §1); exact non-integer
// rationals and flonums become flonums. Non-reals and NaN/±inf are refused.
inline NumCheck num_from_scm(SCM v, Num& out) {
    if (SCM_I_INUMP(v)) {
        out = Num::integer(static_cast<double>(SCM_I_INUM(v)));
        return NumCheck::Ok;
    }
    double d;
    if (SCM_REALP(v)) d = SCM_REAL_VALUE(v);
    else if (scm_is_real(v)) d = scm_to_double(v);
    else return NumCheck::NotReal;
    if (!std::isfinite(d)) return NumCheck::NotFinite;
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
