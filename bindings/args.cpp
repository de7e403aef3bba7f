#include "args.hpp"

#include "keys.hpp"
#include "scm_number.hpp"

namespace ds::guile {

bool mode_from_scm(SCM mode, CollisionMode& out, Failure& f) {
    if (scm_is_eq(mode, keys->swept)) out = CollisionMode::Swept;
    else if (scm_is_eq(mode, keys->discrete)) out = CollisionMode::Discrete;
    else fail(f, "wrong-type-arg", scm_list_1(mode), "collision-mode: expected 'swept or 'discrete, got ~S");
    return !f;
}

bool substeps_from_scm(SCM k, int& out, Failure& f) {
    if (SCM_UNBNDP(k)) {
        out = 1;
        return true;
    }
    if (!SCM_I_INUMP(k) || SCM_I_INUM(k) < 1 || SCM_I_INUM(k) > kMaxSubsteps) {
        fail(f, "wrong-type-arg", scm_list_2(scm_from_int(kMaxSubsteps), k),
             "substeps: expected an exact integer from 1 to ~S, got ~S");
        return false;
    }
    out = static_cast<int>(SCM_I_INUM(k));
    return true;
}

bool dt_from_scm(SCM dt, double& out, Failure& f) {
    Num d;
    if (num_from_scm(dt, d) != NumCheck::Ok) {
        fail(f, "wrong-type-arg", scm_list_1(dt), "dt: expected a finite number of milliseconds, got ~S");
        return false;
    }
    out = d.v;
    return true;
}

}  // namespace ds::guile
