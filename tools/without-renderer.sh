#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The build without SDL2 (docs/render.org, "Without SDL2"), after
# tools/bootstrap.sh has built build/: configures build-norender/ with
# -DDOWNSTROKE_WITH_RENDER=OFF, builds the host and the bindings' tests,
# checks that its (downstroke native) exports exactly the names build/'s
# does (the renderer's procedures as stand-ins), and runs the suites that
# reach the bindings and the Scheme modules there. The C++ core's suites are
# left to build/: the core is the same code in both.
set -euo pipefail
cd "$(dirname "$0")/.."

cmake -S . -B build-norender -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDOWNSTROKE_WITH_RENDER=OFF >/dev/null
cmake --build build-norender -j"$(nproc)" --target downstroke downstroke-bindings-tests
build/bin/downstroke tools/native-names.scm >build-norender/native-names-with.txt
build-norender/bin/downstroke tools/native-names.scm >build-norender/native-names-without.txt
if ! diff -u build-norender/native-names-with.txt build-norender/native-names-without.txt; then
  echo "without-renderer: (downstroke native) differs without the renderer (-: build/, +: build-norender/)" >&2
  exit 1
fi
ctest --test-dir build-norender -j"$(nproc)" -LE slow -R '^(bindings|scheme|docs)\.' --output-on-failure
