#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# install.cmake-package: demo/fall.cpp, as installed, built by a tiny CMake
# project with find_package(Downstroke) and Downstroke::core against the
# prefix, prints what the build tree's copy prints.
source "$(dirname "$0")/common.sh"

cmake -S "$(dirname "$0")/fall-project" -B "$prefix/fall-build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DFALL_SOURCE="$demodir/fall.cpp" -DDEMO_DIR="$demodir" >/dev/null
cmake --build "$prefix/fall-build" >/dev/null
out=$(clean "$prefix/fall-build/fall" "$level")
[ "$out" = "$expected_fall" ] || fail "fall built with find_package printed
$out"
echo "install.cmake-package: fall built with find_package(Downstroke)"
