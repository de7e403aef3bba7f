#!/usr/bin/env bash
# install.pkg-config: demo/fall.cpp, as installed, built with only
# `pkg-config --cflags --libs downstroke' against the prefix, prints what the
# build tree's copy prints.
source "$(dirname "$0")/common.sh"

flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs downstroke)
c++ -std=c++20 -DDS_DEMO_DIR="\"$demodir\"" "$demodir/fall.cpp" $flags -Wl,-rpath,"$libdir" -o "$prefix/fall"
out=$(clean "$prefix/fall" "$level")
[ "$out" = "$expected_fall" ] || fail "fall built with pkg-config printed
$out"
echo "install.pkg-config: fall built with: $flags"
