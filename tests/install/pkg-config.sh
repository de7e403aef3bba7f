#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# install.pkg-config: demo/fall.cpp, as installed, built with only
# `pkg-config --cflags --libs downstroke' against the prefix, prints what the
# build tree's copy prints.
source "$(dirname "$0")/common.sh"

flags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs downstroke)
c++ -std=c++20 -DDS_DEMO_DIR="\"$demodir\"" "$demodir/fall.cpp" $flags -Wl,-rpath,"$libdir" -o "$prefix/fall"
out=$(clean "$prefix/fall" "$level")
[ "$out" = "$expected_fall" ] || fail "fall built with pkg-config printed
$out"

# Exactly the public headers are installed (cmake/public_header_list.cmake).
listed=$(sed -n '/^set(DS_PUBLIC_HEADERS/,/)/p' "$(dirname "$0")/../../cmake/public_header_list.cmake" |
  grep -oE '[a-z_/]+\.(hpp|def)' | sed 's|^|downstroke/|' | sort)
installed=$(cd "$prefix/include" && find downstroke -type f | sort)
[ "$installed" = "$listed" ] || fail "installed headers differ from the list:
$(diff <(echo "$listed") <(echo "$installed"))"
echo "install.pkg-config: fall built with: $flags; the $(wc -l <<<"$listed") public headers installed"
