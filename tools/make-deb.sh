#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the Debian package: downstroke_<version>_<arch>.deb in build-deb/
# (or the directory given: a build directory of its own, configured for /usr
# so that the library lands in Debian's multiarch libdir).
# Install it with: apt-get install ./build-deb/downstroke_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-deb}
# Only what is installed is built (not the tests and benches), and cpack's
# install step then builds nothing more.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_INSTALL_PREFIX=/usr \
      -DCMAKE_SKIP_INSTALL_ALL_DEPENDENCY=ON >/dev/null
cmake --build "$build" -j"${JOBS:-$(nproc)}" \
      --target downstroke-installed downstroke-guile downstroke-core downstroke-scheme
(cd "$build" && cpack -G DEB)
ls "$build"/downstroke_*.deb
