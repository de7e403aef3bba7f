// Argument checks shared by several native procedures (on convert.hpp).
#pragma once
#include <libguile.h>

#include "failure.hpp"
#include "tiles.hpp"

namespace ds::guile {

// 'swept or 'discrete.
bool mode_from_scm(SCM mode, CollisionMode& out, Failure& f);
// Sub-frames per frame: unbound means 1; else an exact integer in
// [1, kMaxSubsteps] (beyond that a frame costs more than any game wants, and
// a typo such as 1e6 would hang the caller).
constexpr int kMaxSubsteps = 1024;
bool substeps_from_scm(SCM k, int& out, Failure& f);
// A finite real number of milliseconds.
bool dt_from_scm(SCM dt, double& out, Failure& f);

}  // namespace ds::guile
