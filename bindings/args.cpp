// SPDX-License-Identifier: MIT
#include "args.hpp"

#include "convert.hpp"
#include "keys.hpp"
#include "scm_number.hpp"

namespace ds::guile {

bool mode_from_scm(SCM mode, CollisionMode& out, Failure& f) {
    if (scm_is_eq(mode, keys->swept)) out = CollisionMode::Swept;
    else if (scm_is_eq(mode, keys->discrete)) out = CollisionMode::Discrete;
    else fail_arg(f, "collision-mode", mode, "'swept or 'discrete");
    return !f;
}

bool push_rule_from_scm(SCM rule, PushRule& out, Failure& f) {
    if (SCM_UNBNDP(rule) || scm_is_eq(rule, keys->clipped)) out = PushRule::Clipped;
    else if (scm_is_eq(rule, keys->seed)) out = PushRule::Seed;
    else fail_arg(f, "push-rule", rule, "'clipped or 'seed");
    return !f;
}

bool substeps_from_scm(SCM k, int& out, Failure& f) {
    if (SCM_UNBNDP(k)) {
        out = 1;
        return true;
    }
    return from_scm(k, out, "substeps", f, 1, kMaxSubsteps);
}

bool gravity_from_scm(SCM g, Num& out, Failure& f) {
    if (SCM_UNBNDP(g)) {
        out = Num::integer(ds::kGravity);  // not PhysKey kGravity (keys.hpp)
        return true;
    }
    double v;
    if (!from_scm(g, v, "gravity", f)) return false;
    num_from_scm(g, out);
    return true;
}

bool dt_from_scm(SCM dt, double& out, Failure& f) {
    // Time runs forwards: a negative dt would run tweens backwards.
    constexpr const char* what = "a finite number of milliseconds ≥ 0";
    if (!from_scm(dt, out, "dt", f, what)) return false;
    if (out >= 0) return true;
    fail_arg(f, "dt", dt, "%s", what);
    return false;
}

}  // namespace ds::guile
