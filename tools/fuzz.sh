#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fuzzing beyond the suite's 10-second runs (docs/limits.org, "Fuzzing and
# sanitizers"). Uses the main build (build/, configured with clang++ and
# libclang-rt-14-dev installed).
#
#   tools/fuzz.sh TARGET MINUTES [JOBS]   fuzz TARGET (tmx, tsx, plist, image, decode) for MINUTES,
#                                         in JOBS parallel processes (default 1)
#   tools/fuzz.sh replay TARGET FILE…     run TARGET's entry point on FILEs, no
#                                         fuzzing (plist: shows the entities built)
# More libFuzzer flags go in FUZZ_FLAGS (-rss_limit_mb=4096 -dict=FILE …).
#
# What a run finds grows build/tests/fuzz/corpus/TARGET, kept between runs. An
# input that fails lands in build/tests/fuzz/artifacts/TARGET/; once fixed,
# it goes to tests/fuzz/regressions/TARGET/, which the suite replays.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
fuzz_dir=$build/tests/fuzz

usage() { sed -n '5,9p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

if [ "${1:-}" = replay ]; then
  (($# >= 3)) || usage
  target=$2; shift 2
  cmake --build "$build" --target "downstroke-replay-$target" >/dev/null
  DS_FUZZ_SHOW=1 exec "$build/bin/downstroke-replay-$target" "$@"
fi

(($# == 2 || $# == 3)) || usage
target=$1 minutes=$2 jobs=${3:-1}
case $target in tmx|tsx|plist|image|decode) ;; *) usage ;; esac
[[ $minutes =~ ^[1-9][0-9]*$ && $jobs =~ ^[1-9][0-9]*$ ]] || usage  # 0 minutes would be -max_total_time=0: no limit
if [ ! -f "$fuzz_dir/$target.args" ]; then
  echo "fuzz.sh: no libFuzzer build in $build/ (configure says why: look for 'libFuzzer targets')" >&2
  exit 1
fi
cmake --build "$build" --target downstroke-fuzzers >/dev/null
mapfile -t args < "$fuzz_dir/$target.args"
# plist: Guile's collector frees by scanning, so leak reports are noise there.
[ "$target" = plist ] && export ASAN_OPTIONS=detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}
# decode: SDL_image's JPEG loader leaks on some refused files (tests/fuzz/lsan-sdl.supp).
[ "$target" = decode ] && export LSAN_OPTIONS=suppressions=$PWD/tests/fuzz/lsan-sdl.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}
parallel=()
((jobs > 1)) && parallel=(-fork="$jobs" -ignore_crashes=0)
echo "fuzz.sh: $target for $minutes min; findings in $fuzz_dir/artifacts/$target/"
exec "$fuzz_dir/clang/bin/fuzz-$target" -max_total_time=$((minutes * 60)) "${parallel[@]}" "${args[@]}" ${FUZZ_FLAGS:-}
