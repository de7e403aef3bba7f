// Guile booted inside the bench process as the downstroke host boots it: the
// native procedures registered in-process, the project's and the bench's
// Scheme directories (sources and compiled .go) on the load paths.
#pragma once

namespace bench {

// Boots Guile in this thread once; later calls do nothing. Compiled modules
// only: it never falls back to compiling at run time.
void ensure_guile();

}  // namespace bench
