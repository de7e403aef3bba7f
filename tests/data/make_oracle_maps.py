#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates tests/data/maps/render/oracle/: small maps, each exercising one
thing Tiled draws, that render.tiled-oracle draws with the engine and with
Tiled's tmxrasterizer and compares pixel by pixel (issue 34).

Every picture is made here (no imaging library: PNGs are written by hand).
Tiles are asymmetric, so a wrong flip, turn or anchor shows. The outputs
are checked in; the build never runs this:
    python3 tests/data/make_oracle_maps.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "maps", "render", "oracle")


def png(path, w, h, pixel):
    """pixel(x, y) -> (r, g, b, a)"""
    raw = b"".join(b"\x00" + bytes(c for x in range(w) for c in pixel(x, y)) for y in range(h))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    with open(os.path.join(OUT, path), "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


BASES = [(200, 60, 40), (60, 160, 70), (50, 90, 210), (220, 190, 40),
         (150, 60, 170), (40, 170, 180), (230, 120, 30), (120, 120, 120)]


def tile_pixel(tid, x, y, size=16):
    """An asymmetric tile: a gradient, a bright top-left corner mark and a
    dark stripe along the bottom; tile 7 is half clear."""
    r, g, b = BASES[tid % len(BASES)]
    if x < 4 and y < 4:
        return (255, 255, 255, 255)
    if y >= size - 3:
        return (20, 20, 20, 255)
    a = 128 if tid == 7 and x >= size // 2 else 255
    return (min(255, r + x * 5), min(255, g + y * 5), b, a)


def sheet():
    # 4 columns × 2 rows of 16×16 tiles
    png("tiles.png", 64, 32, lambda x, y: tile_pixel((y // 16) * 4 + x // 16, x % 16, y % 16))
    # the same with magenta where tile 0's corner mark was, for trans=
    def keyed(x, y):
        p = tile_pixel((y // 16) * 4 + x // 16, x % 16, y % 16)
        return (255, 0, 255, 255) if p == (255, 255, 255, 255) else p
    png("keyed.png", 64, 32, keyed)
    # image-collection tiles of their own sizes
    png("wide.png", 40, 12, lambda x, y: (255, 255, 255, 255) if x < 5 and y < 5 else (30 + x * 5, 200 - y * 10, 90, 255))
    png("tall.png", 10, 30, lambda x, y: (255, 255, 255, 255) if x < 4 and y < 4 else (190, 40 + y * 6, 150 - x * 8, 255))
    # a background picture for image layers
    png("backdrop.png", 24, 20, lambda x, y: (255, 255, 255, 255) if x < 6 and y < 6
        else (40 + x * 8, 60 + y * 8, 120, 255) if (x + y) % 7 else (0, 0, 0, 255))
    png("backdrop-keyed.png", 24, 20, lambda x, y: (255, 0, 255, 255) if 8 <= x < 16 and 6 <= y < 14
        else (40 + x * 8, 60 + y * 8, 120, 255))


TILESET = ' <tileset firstgid="{first}" name="{name}" tilewidth="16" tileheight="16" tilecount="8" columns="4"{extra}>\n{inner}  <image source="{image}" width="64" height="32"{trans}/>\n </tileset>\n'


def tileset(first=1, name="tiles", image="tiles.png", extra="", inner="", trans=""):
    return TILESET.format(first=first, name=name, image=image, extra=extra, inner=inner,
                          trans=f' trans="{trans}"' if trans else "")


def collection(first):
    return (f' <tileset firstgid="{first}" name="things" tilewidth="40" tileheight="30" tilecount="2" columns="0">\n'
            '  <grid orientation="orthogonal" width="1" height="1"/>\n'
            '  <tile id="0"><image source="wide.png" width="40" height="12"/></tile>\n'
            '  <tile id="1"><image source="tall.png" width="10" height="30"/></tile>\n'
            ' </tileset>\n')


def the_map(w, h, body, extra="", tw=16, th=16):
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down" '
            f'width="{w}" height="{h}" tilewidth="{tw}" tileheight="{th}" infinite="0"{extra}>\n' + body + '</map>\n')


def layer(name, w, h, gids, extra="", lid=1):
    return (f' <layer id="{lid}" name="{name}" width="{w}" height="{h}"{extra}>\n'
            f'  <data encoding="csv">{",".join(str(g) for g in gids)}</data>\n </layer>\n')


def objects(name, objs, extra="", lid=2):
    out = f' <objectgroup id="{lid}" name="{name}"{extra}>\n'
    for i, o in enumerate(objs, 1):
        out += f'  <object id="{i}" ' + " ".join(f'{k}="{v}"' for k, v in o.items()) + '/>\n'
    return out + ' </objectgroup>\n'


H, V, D = 0x80000000, 0x40000000, 0x20000000


def write(name, text):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text)


def maps():
    ground = [1, 2, 3, 4, 5, 6, 7, 8] * 2
    # Tile objects with every combination of flips, in file order.
    flips = [0, H, V, D, H | V, H | D, V | D, H | V | D]
    write("tile-object-flips.tmx", the_map(8, 4, tileset() + layer("ground", 8, 4, [0] * 16 + ground) + objects(
        "things", [{"gid": (1 + i) | f, "x": 4 + i * 15, "y": 60 - (i % 2) * 9, "width": 16, "height": 16}
                   for i, f in enumerate(flips)], ' draworder="index"')))
    # Stretched to sizes not their tile's; flipped ones too.
    write("tile-object-stretched.tmx", the_map(10, 5, tileset() + objects(
        "things", [{"gid": 2, "x": 2, "y": 40, "width": 32, "height": 32},
                   {"gid": 3 | H, "x": 40, "y": 34, "width": 24, "height": 12},
                   {"gid": 4 | D, "x": 70, "y": 70, "width": 40, "height": 20},
                   {"gid": 8, "x": 120, "y": 76, "width": 30, "height": 48},
                   {"gid": 5 | V, "x": 10, "y": 78, "width": 48, "height": 8}], ' draworder="index"')))
    # Turned about their anchor.
    write("tile-object-rotated.tmx", the_map(10, 6, tileset() + objects(
        "things", [{"gid": 1, "x": 30, "y": 30, "width": 16, "height": 16, "rotation": 90},
                   {"gid": 2, "x": 70, "y": 40, "width": 16, "height": 16, "rotation": 45},
                   {"gid": 3 | H, "x": 110, "y": 60, "width": 32, "height": 16, "rotation": -30},
                   {"gid": 6, "x": 60, "y": 80, "width": 16, "height": 16, "rotation": 180}], ' draworder="index"')))
    # The draw order Tiled writes by default, topdown: by y, not by index.
    write("draw-order.tmx", the_map(6, 4, tileset() + objects(
        "topdown", [{"gid": 1, "x": 10, "y": 40, "width": 16, "height": 16},
                    {"gid": 2, "x": 18, "y": 30, "width": 16, "height": 16},
                    {"gid": 3, "x": 26, "y": 36, "width": 16, "height": 16}]) + objects(
        "index", [{"gid": 4, "x": 50, "y": 40, "width": 16, "height": 16},
                  {"gid": 5, "x": 58, "y": 30, "width": 16, "height": 16},
                  {"gid": 6, "x": 66, "y": 36, "width": 16, "height": 16}], ' draworder="index"', lid=3)))
    # Each alignment, one tileset per alignment (same picture).
    aligns = ["topleft", "top", "topright", "left", "center", "right", "bottomleft", "bottom", "bottomright"]
    sets = "".join(tileset(first=1 + 8 * i, name=a, extra=f' objectalignment="{a}"') for i, a in enumerate(aligns))
    objs = [{"gid": 1 + 8 * i + (i % 8), "x": 20 + (i % 3) * 40, "y": 20 + (i // 3) * 30, "width": 16, "height": 16}
            for i in range(len(aligns))]
    objs.append({"gid": 1 + 8 * 4, "x": 140, "y": 40, "width": 24, "height": 12, "rotation": 30})
    write("object-alignment.tmx", the_map(12, 7, sets + objects("things", objs, ' draworder="index"')))
    # visible="0" objects and layers.
    write("visibility.tmx", the_map(6, 3, tileset() + layer("hidden", 6, 3, [1] * 18, ' visible="0"') + objects(
        "things", [{"gid": 2, "x": 4, "y": 20, "width": 16, "height": 16},
                   {"gid": 3, "x": 30, "y": 20, "width": 16, "height": 16, "visible": 0}], lid=2)))
    # Image-collection tiles as objects (own sizes, stretched) and in cells.
    write("collection.tmx", the_map(8, 6, tileset() + collection(9) + layer("cells", 8, 6,
        [0] * 16 + [0, 9, 0, 0, 10, 0, 0, 0] + [0] * 24) + objects(
        "things", [{"gid": 9, "x": 10, "y": 80}, {"gid": 10 | H, "x": 60, "y": 90},
                   {"gid": 9 | V, "x": 80, "y": 60, "width": 20, "height": 24}], ' draworder="index"')))
    # Image layers: placed by their offset, repeated along x, y, both.
    write("image-layers.tmx", the_map(10, 8,
        ' <imagelayer id="1" name="once" offsetx="5" offsety="3">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n'
        ' <imagelayer id="2" name="row" offsety="40" repeatx="1">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n'
        ' <imagelayer id="5" name="row-placed" offsetx="0" offsety="60" repeatx="1">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n'
        ' <imagelayer id="3" name="column" offsetx="130" offsety="7" repeaty="1" opacity="0.5">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n'
        ' <imagelayer id="4" name="keyed" offsetx="60" offsety="70">\n  <image source="backdrop-keyed.png" trans="ff00ff" width="24" height="20"/>\n </imagelayer>\n'))
    write("image-layer-both.tmx", the_map(6, 5,
        ' <imagelayer id="1" name="all" offsetx="-7" offsety="9" repeatx="1" repeaty="1">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n'))
    # Opacity, offsets and visibility on layers and groups, nested.
    write("groups.tmx", the_map(8, 6, tileset() +
        layer("base", 8, 6, [(i % 8) + 1 for i in range(48)]) +
        ' <group id="2" name="outer" opacity="0.6" offsetx="6" offsety="-4">\n' +
        layer("inner", 8, 6, [0] * 9 + [4] * 6 + [0] * 33, ' opacity="0.5" offsetx="3" offsety="2"', lid=3) +
        objects("props", [{"gid": 7, "x": 30, "y": 80, "width": 16, "height": 16}], ' offsetx="-5"', lid=4) +
        '  <group id="5" name="hidden" visible="0">\n' + layer("never", 8, 6, [2] * 48, lid=6) + '  </group>\n'
        ' </group>\n' + layer("top", 8, 6, [0] * 40 + [5, 0, 6, 0, 0, 0, 0, 0], ' offsetx="-3"', lid=7)))
    # Fractional offsets, rounded as Tiled rounds them (floor(offset + 0.5)),
    # on tile, object and image layers; a group's summed with its layer's
    # before rounding (0.5 + 0.5 moves 1 px, not 2).
    write("fractional-offsets.tmx", the_map(8, 6, tileset() +
        layer("base", 8, 6, [1] * 48) +
        layer("halves", 8, 6, [0] * 9 + [2] + [0] * 38, ' offsetx="2.5" offsety="-1.5"', lid=2) +
        ' <group id="3" name="outer" offsetx="0.5" offsety="-2.5">\n' +
        layer("inner", 8, 6, [0] * 12 + [3] + [0] * 35, ' offsetx="0.5" offsety="0.5"', lid=4) +
        objects("props", [{"gid": 7, "x": 16, "y": 80, "width": 16, "height": 16}], ' offsetx="-0.5" offsety="0.25"',
                lid=5) +
        ' </group>\n'
        ' <imagelayer id="6" name="picture" offsetx="80.5" offsety="60.5">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n' +
        layer("thirds", 8, 6, [0] * 46 + [5, 0], ' offsetx="-3.5" offsety="1.4999"', lid=7)))
    # A tintcolor without its '#' is no colour to Tiled: the layers are drawn
    # untinted. (Tiled 1.8 draws no tint at all, and its JSON twin leaves
    # the tints out; map-draw checks, from TMX and JSON, that a '#'-less
    # tint is left out where a tint would show.)
    write("tint-without-hash.tmx", the_map(6, 3, tileset() +
        ' <group id="1" name="tinted" tintcolor="80ff00ff">\n' +
        layer("cells", 6, 3, [(i % 8) + 1 for i in range(18)], ' tintcolor="ff0000"', lid=2) +
        objects("things", [{"gid": 3, "x": 40, "y": 40, "width": 16, "height": 16}], ' tintcolor="00ff00"', lid=3) +
        ' </group>\n'))
    # <tileoffset> on cells and on tile objects (scaled with the object).
    write("tile-offset.tmx", the_map(8, 5, tileset(extra="", inner='  <tileoffset x="3" y="-5"/>\n') +
        layer("cells", 8, 5, [0] * 9 + [1, 2, 3] + [0] * 28) + objects(
        "things", [{"gid": 4, "x": 60, "y": 70, "width": 16, "height": 16},
                   {"gid": 5, "x": 90, "y": 70, "width": 32, "height": 32}], ' draworder="index"')))
    # The image's colour key.
    write("trans.tmx", the_map(6, 3, tileset(image="keyed.png", trans="ff00ff") +
        layer("cells", 6, 3, [1, 2, 3, 4, 5, 6] * 3)))
    # The map's background colour, behind half-clear tiles.
    write("background.tmx", the_map(6, 3, tileset() + layer("cells", 6, 3, [8, 0, 8, 1, 8, 0] * 3),
        ' backgroundcolor="#3a6b2c"'))
    # Tiles larger than a cell, in each render order.
    big = (' <tileset firstgid="1" name="big" tilewidth="32" tileheight="32" tilecount="2" columns="2">\n'
           '  <image source="tiles.png" width="64" height="32"/>\n </tileset>\n')
    for order in ["right-down", "right-up", "left-down", "left-up"]:
        write(f"render-order-{order}.tmx", the_map(6, 5, big + layer("big", 6, 5,
            [1, 2, 1, 2, 1, 2, 2, 1, 2, 1, 2, 1] + [1, 0, 2, 0, 1, 2] + [0, 1, 2, 1, 0, 1] + [2, 2, 1, 1, 2, 2]))
            .replace('renderorder="right-down"', f'renderorder="{order}"'))
    # Layers of every kind interleaved as the file has them.
    write("interleaved.tmx", the_map(8, 5, tileset() +
        ' <imagelayer id="1" name="back" repeatx="1" repeaty="1">\n  <image source="backdrop.png" width="24" height="20"/>\n </imagelayer>\n' +
        layer("floor", 8, 5, [0] * 24 + [1, 2, 3, 4, 5, 6, 7, 8] + [2] * 8, lid=2) +
        objects("middle", [{"gid": 3, "x": 20, "y": 70, "width": 32, "height": 32}], lid=3) +
        ' <group id="4" name="front">\n' + layer("grass", 8, 5, [0] * 32 + [0, 6, 6, 0, 0, 6, 0, 0], lid=5) +
        '  <imagelayer id="6" name="fog" opacity="0.25" offsetx="40">\n   <image source="backdrop.png" width="24" height="20"/>\n  </imagelayer>\n'
        ' </group>\n'))


def json_twins():
    import shutil
    import subprocess
    if not shutil.which("tiled"):
        print("tiled is not installed: the .tmj twins are left as they are")
        return
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    for name in sorted(os.listdir(OUT)):
        if name.endswith(".tmx"):
            subprocess.run(["tiled", "--export-map", "json", name, name[:-4] + ".tmj"], cwd=OUT, env=env,
                           check=True, stderr=subprocess.DEVNULL)


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    sheet()
    maps()
    json_twins()
