// Argument checks shared by several native procedures.
#pragma once
#include <libguile.h>

#include "failure.hpp"
#include "tiles.hpp"

namespace ds::guile {

// 'swept or 'discrete.
bool mode_from_scm(SCM mode, CollisionMode& out, Failure& f);
// A finite real number of milliseconds.
bool dt_from_scm(SCM dt, double& out, Failure& f);

}  // namespace ds::guile
