// SPDX-License-Identifier: MIT
// Argument checks shared by several native procedures (on convert.hpp).
#pragma once
#include <libguile.h>

#include "constants.hpp"
#include "failure.hpp"
#include "tiles.hpp"

namespace ds::guile {

// 'swept or 'discrete.
bool mode_from_scm(SCM mode, CollisionMode& out, Failure& f);
// 'clipped or 'seed; unbound means 'clipped, the default.
bool push_rule_from_scm(SCM rule, PushRule& out, Failure& f);
// Sub-frames per frame: unbound means 1; else an exact integer in
// [1, kMaxSubsteps] (constants.hpp says why).
bool substeps_from_scm(SCM k, int& out, Failure& f);
// A finite real number of milliseconds, ≥ 0 (-0.0 included).
bool dt_from_scm(SCM dt, double& out, Failure& f);
// The scene's gravity (semantics §14): unbound means the seed's *gravity*;
// else a finite real number, exact when an exact integer.
bool gravity_from_scm(SCM g, Num& out, Failure& f);

}  // namespace ds::guile
