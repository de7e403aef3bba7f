#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the pictures the test maps name, so that loading them finds every
image (a missing one is a warning, or strict?'s error, since issue 46) and
the tests about something else see only the warnings they are about. Each
is a plain grey PNG of the size its map or tileset declares; no test reads
their pixels (the render tests draw render/sheet.png, made by
render/make_render_maps.py). render/absent.png is left missing on purpose:
no-image.tmx is the map whose picture is not there. Run it from anywhere;
it writes beside itself."""
import os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))

# path (relative to this folder): the width and height its map declares.
IMAGES = {
    "features/a.png": (32, 32),
    "features/anim.png": (64, 16),
    "features/f.png": (32, 32),
    "features/one.png": (48, 16),
    "features/shapes.png": (16, 16),
    "features/sky.png": (320, 200),
    "images/bush.png": (32, 32),
    "images/props.png": (36, 36),
    "images/sky.png": (64, 24),
    "images/terrain.png": (64, 32),
    "images/tree.png": (32, 32),
    "json/features/shapes.png": (16, 16),
    "json/images/bush.png": (32, 32),
    "json/images/props.png": (36, 36),
    "json/images/sky.png": (64, 24),
    "json/images/terrain.png": (64, 32),
    "json/images/tree.png": (32, 32),
    "scheme/art/sky.png": (320, 240),
    "scheme/art/tiles.png": (70, 36),
    "scheme/props/barrel.png": (24, 32),
    "scheme/props/lamp.png": (8, 32),
    "scheme/two.png": (32, 16),
}

def grey_png(path, width, height):
    rows = (b"\0" + b"\x80" * width) * height  # 8-bit grey, no filter
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))

for name, (w, h) in IMAGES.items():
    grey_png(os.path.join(HERE, name), w, h)
