# SPDX-License-Identifier: MIT
# Sourced by the install.* scripts: their arguments (tests/install/CMakeLists.txt),
# a fresh install into $prefix, and `clean', which runs a command with only
# the environment it is given (no variable from the caller's shell).
set -euo pipefail
build=$1 prefix=$2 build_fall=$3
bindir=$prefix/$4 libdir=$prefix/$5 extdir=$prefix/$6 sitedir=$prefix/$7 ccachedir=$prefix/$8 demodir=$prefix/$9
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
mkdir -p "$prefix/home" "$prefix/cache"

clean() { env -i PATH=/usr/bin:/bin HOME="$prefix/home" XDG_CACHE_HOME="$prefix/cache" "$@"; }

fail() { echo "FAIL: $*" >&2; exit 1; }

# The C++ demo's trace on the installed map: what every copy must print.
level=$demodir/maps/level1.tmx
expected_fall=$("$build_fall" "$level")
