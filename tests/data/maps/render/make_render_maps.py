#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the render tests' map: sheet.png, a 2 x 2 sheet of 8 x 8 tiles in
which every pixel of every tile has its own colour,

    colour(tile t, pixel u, v) = (40 + 50 t, 20 + 25 u, 10 + 30 v),

so a test can tell from one pixel which tile, which pixel of it, and which
way up it was drawn; sheet.tsx; and render.tmx, 6 x 4 cells with one tile of
each flip. Run it from anywhere; it writes beside itself."""
import os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
TILE = 8

def colour(t, u, v):
    return (40 + 50 * t, 20 + 25 * u, 10 + 30 * v)

def png(path, width, height, pixel):
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))

png(os.path.join(HERE, "sheet.png"), 2 * TILE, 2 * TILE,
    lambda x, y: colour((y // TILE) * 2 + x // TILE, x % TILE, y % TILE))

with open(os.path.join(HERE, "sheet.tsx"), "w") as f:
    f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<tileset version="1.10" tiledversion="1.10.2" name="sheet" tilewidth="8" tileheight="8" tilecount="4" columns="2">\n'
            ' <image source="sheet.png" width="16" height="16"/>\n'
            ' <tile id="0"><properties><property name="solid" type="bool" value="true"/></properties></tile>\n'
            '</tileset>\n')

H, V, D = 0x80000000, 0x40000000, 0x20000000
cells = [
    [2, 2 | H, 2 | V, 2 | D, 2 | H | V, 2 | D | H],
    [3, 0, 0, 0, 0, 4],
    [0, 0, 0, 0, 0, 0],
    [1, 1, 1, 1, 1, 1],
]
with open(os.path.join(HERE, "render.tmx"), "w") as f:
    f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" '
            'width="6" height="4" tilewidth="8" tileheight="8" infinite="0" nextlayerid="2" nextobjectid="1">\n'
            ' <tileset firstgid="1" source="sheet.tsx"/>\n'
            ' <layer id="1" name="tiles" width="6" height="4">\n  <data encoding="csv">\n')
    f.write(",\n".join(",".join(str(c) for c in row) for row in cells))
    f.write('\n</data>\n </layer>\n</map>\n')

# The same map with its image missing: loading must not need it.
with open(os.path.join(HERE, "no-image.tsx"), "w") as f:
    f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<tileset version="1.10" tiledversion="1.10.2" name="gone" tilewidth="8" tileheight="8" tilecount="4" columns="2">\n'
            ' <image source="absent.png" width="16" height="16"/>\n'
            '</tileset>\n')
with open(os.path.join(HERE, "no-image.tmx"), "w") as f:
    f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" '
            'width="2" height="1" tilewidth="8" tileheight="8" infinite="0" nextlayerid="2" nextobjectid="1">\n'
            ' <tileset firstgid="1" source="no-image.tsx"/>\n'
            ' <layer id="1" name="tiles" width="2" height="1">\n  <data encoding="csv">\n1,2\n</data>\n </layer>\n</map>\n')
