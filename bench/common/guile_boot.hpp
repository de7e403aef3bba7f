// SPDX-License-Identifier: MIT
// Guile booted inside the bench process as the downstroke host boots it: the
// native procedures registered in-process, the project's and the bench's
// Scheme directories (sources and compiled .go) on the load paths.
#pragma once
#include <libguile.h>

#include <string>

namespace bench {

// Boots Guile in this thread once; later calls do nothing. Compiled modules
// only: it never falls back to compiling at run time.
void ensure_guile();

// The running Guile's version (boots Guile first).
std::string guile_version();

// A caught Scheme error, (key . args), as text for a report.
std::string error_text(SCM key, SCM args);

}  // namespace bench
