#!/usr/bin/env bash
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

# demo frame [extra arguments for the demo]
capture() {
  local demo=$1 frame=$2
  shift 2
  build/bin/downstroke --capture "$tmp/$demo" "demo/$demo.scm" "$@" >/dev/null
  cp "$tmp/$demo/$(printf '%06d' "$frame").png" "$out/$demo.png"
  echo "docs/images/$demo.png: frame $frame of demo/$demo.scm"
}

capture platformer 140
capture topdown 120
capture sandbox 200
capture shmup 150
capture tweens 60
