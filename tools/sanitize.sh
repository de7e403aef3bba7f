#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The ASan+UBSan run (docs/limits.org, "Fuzzing and sanitizers"): configures
# build-asan/ with DOWNSTROKE_SANITIZE=ON (GCC), builds only what the checked
# suites need, and runs them: every C++ suite, the fuzz targets' replays, and
# the Scheme suites named below. Extra arguments go to ctest (-R, -V, …).
# Not in .ci/run: it takes longer than CI's whole test stage.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build-asan
jobs=${JOBS:-$(nproc)}

# The Scheme suites worth their time under ASan: the native steps (physics),
# scenes and frames (world), maps (tilemap), tweens and entities, and what a
# script can do to a running game (run-limits: stack, re-entry, sizes), and
# golden frames read and compared (testing).
scheme_suites="physics|world|tilemap|tween|entity|run-limits|testing"
tests="^(core|bindings|render)\.|^fuzz\.replay\.|^scheme\.($scheme_suites)-test$"

cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDOWNSTROKE_SANITIZE=ON >/dev/null
targets=(downstroke downstroke-core-tests downstroke-bindings-tests
         downstroke-replay-tmx downstroke-replay-tsx downstroke-replay-plist downstroke-replay-image)
# (grep reads all of make's list: -q would end the pipe early, and pipefail fail it)
cmake --build "$dir" --target help | grep downstroke-render-tests >/dev/null &&
  targets+=(downstroke-render-tests downstroke-tiled-oracle downstroke-replay-decode)
cmake --build "$dir" -j"$jobs" --target "${targets[@]}"
ctest --test-dir "$dir" -j"$jobs" --output-on-failure -R "$tests" "$@"
