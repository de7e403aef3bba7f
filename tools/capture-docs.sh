#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the pictures in docs/images/: each demo is run headless with
# `downstroke --capture` (its scripted input, off-screen drawing) and the
# frame that shows it best is kept. Nothing here is drawn by hand.
# Usage: bash tools/capture-docs.sh   (after tools/bootstrap.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/images
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# capture DEMO FRAME [NAME [HOST OPTIONS…]]
capture() {
  local demo=$1 frame=$2 name=${3:-$1}
  shift $(( $# < 3 ? $# : 3 ))
  build/bin/downstroke "$@" --capture "$tmp/$name" "demo/$demo.scm" >/dev/null
  cp "$tmp/$name/$(printf '%06d' "$frame").png" "$out/$name.png"
  echo "docs/images/$name.png: frame $frame of demo/$demo.scm $*"
}

capture platformer 70
capture platformer 458 platformer-beyond
capture platformer 281 platformer-hill
capture topdown 60
capture sandbox 60
capture shmup 24
capture tweens 14
capture fall 45
capture sandbox 60 sandbox-debug --debug
capture platformer 44 platformer-front
# The five short examples (demo/examples/), each at the frame that shows its idea.
capture examples/jump 34 example-jump
capture examples/plank 45 example-plank
capture examples/ramp 34 example-ramp
capture examples/pickup 12 example-pickup
capture examples/tween 14 example-tween

# render.org's pictures of what a Tiled map draws: each feature map of the
# oracle test drawn by the engine (left) and by Tiled's tmxrasterizer
# (right), three times their size.
if command -v tmxrasterizer >/dev/null; then
  QT_QPA_PLATFORM=offscreen build/bin/downstroke-tiled-oracle --keep "$tmp/oracle" --doc "$out" \
    tests/data/maps/render/oracle/*.tmx >/dev/null
  echo "docs/images/render-*.png: tests/data/maps/render/oracle/*.tmx, the engine beside Tiled"
else
  echo "tmxrasterizer is absent (Debian's package tiled): docs/images/render-*.png kept as they are" >&2
fi
