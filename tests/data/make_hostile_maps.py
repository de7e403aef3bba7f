#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the hostile maps under tests/data/maps/hostile, which the audit of
issue 19 built to exhaust, hang or confuse the loader; tests/core/
hostile_maps_test.cpp and tests/scheme/hostile-maps-test.scm assert that each
ends in an error naming the file. Run it from anywhere:
    python3 tests/data/make_hostile_maps.py
The outputs are checked in (the largest, zstd_bomb.tmx, is about 180 KB).
Inputs that would be large on disk (a CSV of millions of cells) or cannot be
committed (a FIFO) are made by the tests in a temporary directory instead.

Each map keeps make_maps.small_map's layout unless its comment says
otherwise, so the tests can assert line numbers: the <map> on line 2, the
<tileset> on 3, the <layer> on 4, its <data> on 5.
"""
import gzip
import os
import zlib

from make_maps import H, TILESET_LINE, b64, b64_data, le_bytes, small_map, zstd

HERE = os.path.dirname(os.path.abspath(__file__))
HOSTILE = os.path.join(HERE, "maps", "hostile")

INFINITE = 'orientation="orthogonal" width="2" height="2" tilewidth="16" tileheight="16" infinite="1"'


def map_attrs(width=2, height=2, tilewidth=16, tileheight=16):
    return (f'orientation="orthogonal" width="{width}" height="{height}" '
            f'tilewidth="{tilewidth}" tileheight="{tileheight}"')


def write(name, text):
    os.makedirs(HOSTILE, exist_ok=True)
    with open(os.path.join(HOSTILE, name), "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


def zstd_bomb():
    """64 layers of 4096x4096 zstd cells: 180 KB that decode to 4 GB. Layer
    number i (from 0) is on line 4 + 3i."""
    payload = b64(zstd(bytes(4096 * 4096 * 4)))
    layers = "".join(
        f' <layer id="{i + 1}" name="layer{i}" width="4096" height="4096">\n'
        f'  <data encoding="base64" compression="zstd">{payload}</data>\n'
        f' </layer>\n' for i in range(64))
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<map version="1.10" {map_attrs(4096, 4096)}>\n'
            f' {TILESET_LINE}\n{layers}</map>\n')


def nested_groups(depth):
    """`depth` nested <group>s around one layer; group k (from 1) on line 2 + k."""
    opens = "".join(f'{" " * k}<group id="{k}" name="g{k}">\n' for k in range(1, depth + 1))
    closes = "".join(f'{" " * k}</group>\n' for k in range(depth, 0, -1))
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<map version="1.10" {map_attrs()}>\n{opens}'
            f'<layer id="999" name="deep" width="2" height="2"><data encoding="csv">0,0,0,0</data></layer>\n'
            f'{closes}</map>\n')


def tileset_with(attrs, image=""):
    return (f'<tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="8" '
            f'columns="4"{attrs}>{image}</tileset>')


def maps():
    ok = '<data encoding="csv">1,2,3,4</data>'
    four = le_bytes([1, 2, 3, 4])
    # The second tileset on line 4 (the layer on 5, its data on 6).
    two_tilesets = TILESET_LINE + "\n " + TILESET_LINE.replace('name="t"', 'name="u"')
    return {
        "zstd_bomb.tmx": zstd_bomb(),
        # 2x2 layers whose streams hold 64 MB (zstd) and 8 MB (deflate, which
        # packs zeros 1000:1 at best): decoding stops past 16 bytes.
        "zstd_overlong.tmx": small_map(b64_data(None, "zstd", b64(zstd(bytes(64 << 20))))),
        "zlib_overlong.tmx": small_map(b64_data(None, "zlib", b64(zlib.compress(bytes(8 << 20), 9)))),
        "gzip_overlong.tmx": small_map(b64_data(None, "gzip", b64(gzip.compress(bytes(8 << 20), 9, mtime=0)))),
        "zstd_short.tmx": small_map(b64_data(None, "zstd", b64(zstd(four[:12])))),
        # Tilesets that are not files.
        "tileset_urandom.tmx": small_map(ok, tileset='<tileset firstgid="1" source="/dev/urandom"/>'),
        "tileset_zero.tmx": small_map(ok, tileset='<tileset firstgid="1" source="/dev/zero"/>'),
        # Header and layers that disagree.
        "zero_size.tmx": small_map(ok, map_attrs=map_attrs(0, 0), layer_attrs='width="6" height="4"'),
        "layer_wider.tmx": small_map(ok, layer_attrs='width="6" height="2"'),
        "layer_default_size.tmx": small_map('<data encoding="csv">1,2,3,4,1,2</data>',
                                            map_attrs=map_attrs(3, 2), layer_attrs=""),
        "huge_tilewidth.tmx": small_map(ok, map_attrs=map_attrs(tilewidth=2147483647)),
        "far_chunk.tmx": small_map(
            '<data encoding="csv"><chunk x="2000000000" y="0" width="1" height="1">1</chunk></data>',
            map_attrs=INFINITE.replace('tilewidth="16"', 'tilewidth="16777216"')),
        # Three overlapping 16x16 chunks: 768 cells decoded for a 256-cell layer.
        "overlapping_chunks.tmx": small_map(
            '<data encoding="csv">' + "".join(
                f'<chunk x="0" y="0" width="16" height="16">{",".join(["1"] * 256)}</chunk>'
                for _ in range(3)) + '</data>', map_attrs=INFINITE),
        # gids and tilesets.
        "negative_firstgid.tmx": small_map(ok, tileset=TILESET_LINE.replace('firstgid="1"', 'firstgid="-1"')),
        "huge_firstgid.tmx": small_map(ok, tileset=TILESET_LINE.replace('firstgid="1"', 'firstgid="4294967295"')),
        "firstgid_past_gids.tmx": small_map(
            '<data encoding="csv">0,0,0,0</data>',
            tileset=TILESET_LINE.replace('firstgid="1"', 'firstgid="268435450"')),
        "duplicate_firstgid.tmx": small_map(ok, tileset=two_tilesets),
        "flip_bits_gid.tmx": small_map(f'<data encoding="csv">{0xFFFFFFFF},0,0,0</data>'),
        "gid_past_tilecount.tmx": small_map(f'<data encoding="csv">{9 | H},0,0,0</data>'),
        # Layer data of the wrong length or with junk.
        "base64_three_chars.tmx": small_map(b64_data(None, payload="AQA")),
        "base64_junk.tmx": small_map(b64_data(None, payload="AQAAAA%%AAAA")),
        "csv_long.tmx": small_map('<data encoding="csv">1,2,3,4,5,6,7,8</data>'),
        "csv_short.tmx": small_map('<data encoding="csv">1,2</data>'),
        "csv_junk.tmx": small_map('<data encoding="csv">1,2,3,4;</data>'),
        "xml_long.tmx": small_map('<data>' + '<tile gid="1"/>' * 9 + '</data>'),
        # Nesting.
        "deep_groups.tmx": nested_groups(40),
        "deeper_than_xml.tmx": nested_groups(150),
        # Tilesets that name tilesets: the loader never follows them.
        "tileset_self.tmx": small_map(ok, tileset='<tileset firstgid="1" source="tilesets/self.tsx"/>'),
        # Absurd sizes in tilesets.
        "tileset_huge_image.tmx": small_map(
            ok, tileset=tileset_with("", '<image source="t.png" width="2147483647" height="32"/>')),
        "tileset_huge_spacing.tmx": small_map(ok, tileset=tileset_with(' spacing="2147483647"')),
        "tileset_huge_tile.tmx": small_map(
            ok, tileset=TILESET_LINE.replace('tilewidth="16"', 'tilewidth="2147483647"')),
        "tile_huge_image.tmx": small_map(
            ok, tileset=tileset_with("", '<tile id="0"><image source="a.png" width="16" height="99999999"/></tile>')),
        # A tile object upside down: its height reached back past its corner,
        # which once sized the drawing index at no rows and corrupted the heap.
        # Its <object> on line 8.
        "object_negative_height.tmx": with_objects(
            ok, '<object id="1" gid="1" x="0" y="32" width="16" height="-50"/>'),
        # A collision polygon of 6000 points (its <objectgroup> on line 3): each
        # cell showing the tile once simplified it again, in quadratic time.
        "polygon_bomb.tmx": small_map(ok, tileset=tileset_with(
            "", '<tile id="0"><objectgroup><object id="1" x="0" y="0"><polygon points="' +
            " ".join(f"{i % 17},{i % 13}" for i in range(6000)) + '"/></object></objectgroup></tile>')),
    }


def with_objects(data, objects):
    """small_map with an object layer after the tile layer: its <objectgroup>
    on line 7, its first object on 8."""
    return small_map(data).replace(
        '</map>\n', f' <objectgroup id="2" name="things">\n  {objects}\n </objectgroup>\n</map>\n')


def main():
    for name, text in maps().items():
        write(name, text)
    os.makedirs(os.path.join(HOSTILE, "tilesets"), exist_ok=True)
    # A .tsx whose own <tileset> names itself as its source.
    with open(os.path.join(HOSTILE, "tilesets", "self.tsx"), "w", encoding="utf-8", newline="\n") as f:
        f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                '<tileset source="self.tsx" name="self" tilewidth="16" tileheight="16" tilecount="8" columns="4">\n'
                '</tileset>\n')


if __name__ == "__main__":
    main()
