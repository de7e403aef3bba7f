#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Sets up a fresh Debian 12 machine for Downstroke and builds it: installs the
# Debian packages the build needs (only those missing), then configures and
# builds into build/. Run as root, or as a user with sudo. Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."

# libbox2d-dev and gnuplot-nox only serve the benchmarks (the box2d path; the accuracy plot);
# the SDL2 set is the renderer (window, capture, input, sound), with libvorbis-dev (libvorbisfile:
# Ogg sounds are decoded by the sound bank itself, capped at the length they claim) and libasound2-dev (alsa-lib,
# given a silent error handler so that a machine without a sound card prints only the engine's one line); xvfb, xauth, x11-apps (xwd)
# and xdotool serve the one test that opens a real window on a virtual display; clang and
# libclang-rt-dev (libFuzzer, not pulled in by --no-install-recommends) build the fuzz targets;
# emacs-nox and elpa-geiser (Debian 12's Geiser 0.10, Guile support included) run the test
# that attaches Geiser to a served game; nlohmann-json3-dev (header-only) reads Tiled's JSON
# maps, tilesets, templates and project files; python3 and python3-zstandard run the tilemap
# corpus test's independent decoder (tests/tilemap_corpus/decode_tiled.py); tiled brings
# tmxrasterizer, Tiled's own renderer, the oracle render.tiled-oracle compares drawn maps with.
packages=(make pkg-config guile-3.0-dev libtinyxml2-dev doctest-dev zlib1g-dev libzstd-dev nlohmann-json3-dev libbox2d-dev gnuplot-nox
          libsdl2-dev libsdl2-image-dev libsdl2-mixer-dev libvorbis-dev libasound2-dev xvfb xauth x11-apps xdotool clang libclang-rt-dev
          emacs-nox elpa-geiser python3 python3-zstandard tiled)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "bootstrap: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)"
