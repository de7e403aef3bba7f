#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates the Tiled maps under tests/data/maps used by tests/core/tilemap_test.cpp.

The outputs are checked in; the build never runs this. Run it from anywhere:
    python3 tests/data/make_maps.py
zlib and gzip come from Python's modules (gzip with mtime=0 so the output is
stable); zstd from the `zstd` command-line tool, once with the frame's content
size recorded and once without, so both decoder paths are exercised.

Files under maps/bad/ are deliberately broken; their layout is fixed so the
tests can assert line numbers (see the comments on small_map).
"""
import base64
import gzip
import os
import struct
import subprocess
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
MAPS = os.path.join(HERE, "maps")

H, V, D, R = 0x80000000, 0x40000000, 0x20000000, 0x10000000

# The level every encoding map holds: 6x4 cells over tilesets/terrain.tsx,
# with each of the four flip/rotation bits set somewhere.
LEVEL = [
    0, 0, 7, 0, 0, 8 | H,
    0, 5, 0, 0, 6, 0,
    1 | H, 0, 0, 0, 0, 4 | V,
    1, 2, 3, 3 | V | D, 2, 1 | H | V | D | R,
]


def write(rel, text):
    path = os.path.join(MAPS, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


def le_bytes(gids):
    return b"".join(struct.pack("<I", g) for g in gids)


def b64(data):
    return base64.b64encode(data).decode("ascii")


def zstd(data, content_size=True):
    with tempfile.NamedTemporaryFile(delete=False) as tmp:
        tmp.write(data)
    try:
        args = ["zstd", "-q", "-c", "-19"]
        if not content_size:
            args.append("--no-content-size")
        return subprocess.run(args + [tmp.name], check=True, capture_output=True).stdout
    finally:
        os.unlink(tmp.name)


def csv(gids, width):
    rows = [",".join(str(g) for g in gids[i:i + width]) for i in range(0, len(gids), width)]
    return ",\n".join(rows)


def data_element(gids, width, encoding, indent="  "):
    """A <data> element in the given encoding, laid out as Tiled writes it."""
    raw = le_bytes(gids)
    if encoding == "csv":
        return f'{indent}<data encoding="csv">\n{csv(gids, width)}\n{indent}</data>'
    if encoding == "xml":
        tiles = "\n".join(f'{indent} <tile gid="{g}"/>' if g else f"{indent} <tile/>" for g in gids)
        return f"{indent}<data>\n{tiles}\n{indent}</data>"
    packed = {
        "base64": (None, raw),
        "zlib": ("zlib", zlib.compress(raw, 9)),
        "gzip": ("gzip", gzip.compress(raw, 9, mtime=0)),
        "zstd": ("zstd", zstd(raw)),
        "zstd_stream": ("zstd", zstd(raw, content_size=False)),
    }[encoding]
    comp = f' compression="{packed[0]}"' if packed[0] else ""
    return f'{indent}<data encoding="base64"{comp}>\n   {b64(packed[1])}\n{indent}</data>'


TERRAIN_TSX = """<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.10.2" name="terrain" tilewidth="16" tileheight="16" tilecount="8" columns="4">
 <image source="../images/terrain.png" width="64" height="32"/>
 <tile id="0">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1">
  <properties>
   <property name="collision" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="2">
  <properties>
   <property name="collides" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="3">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="8" width="16" height="8"/>
  </objectgroup>
 </tile>
 <tile id="4">
  <properties>
   <property name="solid" type="bool" value="false"/>
  </properties>
 </tile>
 <tile id="5">
  <objectgroup draworder="index" id="2"/>
 </tile>
 <tile id="7" class="spikes">
  <properties>
   <property name="collision" value="TRUE"/>
   <property name="damage" type="int" value="3"/>
  </properties>
 </tile>
 <tile id="6" type="ladder">
  <properties>
   <property name="climbable" type="bool" value="true"/>
  </properties>
  <animation>
   <frame tileid="6" duration="100"/>
  </animation>
 </tile>
 <wangsets/>
</tileset>
"""


def level_map(encoding):
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" width="6" height="4" tilewidth="16" tileheight="16" infinite="0" nextlayerid="2" nextobjectid="1">
 <properties>
  <property name="title" value="level"/>
  <property name="gravity" type="float" value="0.5"/>
 </properties>
 <tileset firstgid="1" source="tilesets/terrain.tsx"/>
 <layer id="1" name="ground" width="6" height="4">
{data_element(LEVEL, 6, encoding)}
 </layer>
</map>
"""


def chunk(x, y, w, gids, encoding):
    """A <chunk> laid out like Tiled's: a <data> body retagged, the encoding
    attributes left to the enclosing <data>."""
    body = data_element(gids, w, encoding, indent="   ").strip().split(">", 1)[1]
    head = f'<chunk x="{x}" y="{y}" width="{w}" height="{len(gids) // w}">'
    return "   " + head + body.replace("</data>", "</chunk>")


INFINITE = f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" width="30" height="20" tilewidth="16" tileheight="16" infinite="1" nextlayerid="4" nextobjectid="1">
 <tileset firstgid="1" source="tilesets/terrain.tsx"/>
 <layer id="1" name="ground" width="30" height="20">
  <data encoding="csv">
{chunk(-4, -2, 4, [1, 1, 1, 1, 0, 0, 5, 0], "csv")}
{chunk(0, 0, 4, [2, 0, 0, 3, 2, 2, 2, 2], "csv")}
  </data>
 </layer>
 <layer id="2" name="overhang" width="30" height="20">
  <data encoding="base64" compression="zlib">
{chunk(4, -4, 4, [0, 0, 4, 4, 8 | H, 0, 0, 0], "zlib")}
  </data>
 </layer>
 <layer id="3" name="empty" width="30" height="20">
  <data encoding="csv"/>
 </layer>
</map>
"""

# Three tilesets, written out of firstgid order: the loader sorts them.
TILESETS = f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" width="6" height="2" tilewidth="16" tileheight="16" infinite="0" nextlayerid="2" nextobjectid="1">
 <tileset firstgid="13" name="deco" tilewidth="32" tileheight="32" tilecount="0" columns="0">
  <grid orientation="orthogonal" width="1" height="1"/>
  <tile id="0">
   <image width="32" height="32" source="images/tree.png"/>
  </tile>
  <tile id="5" type="bush">
   <properties>
    <property name="solid" type="bool" value="true"/>
   </properties>
   <image width="32" height="32" source="images/bush.png"/>
  </tile>
 </tileset>
 <tileset firstgid="1" source="tilesets/terrain.tsx"/>
 <tileset firstgid="9" name="props" tilewidth="16" tileheight="16" spacing="1" margin="2" tilecount="4" columns="2">
  <image source="images/props.png" width="36" height="36"/>
  <tile id="0">
   <properties>
    <property name="solid" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="2">
   <objectgroup draworder="index" id="2">
    <object id="1" x="0" y="0">
     <polygon points="0,0 16,0 16,16"/>
    </object>
   </objectgroup>
  </tile>
  <tile id="3">
   <properties>
    <property name="collides" type="bool" value="false"/>
   </properties>
  </tile>
 </tileset>
 <layer id="1" name="mixed" width="6" height="2">
{data_element([1, 8, 9, 10, 11, 12, 9 | H, 11 | V, 13, 18, 100, 0], 6, "csv")}
 </layer>
</map>
"""

LAYERS = """<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" width="4" height="3" tilewidth="16" tileheight="8" infinite="0" nextlayerid="10" nextobjectid="6">
 <tileset firstgid="1" source="tilesets/terrain.tsx"/>
 <layer id="1" name="background" width="4" height="3">
  <data encoding="csv">
5,1,0,0,
0,0,0,0,
0,0,0,0
</data>
 </layer>
 <group id="2" name="world">
  <properties>
   <property name="note" value="group"/>
  </properties>
  <layer id="3" name="walls" width="4" height="3">
   <properties>
    <property name="solid" type="bool" value="true"/>
   </properties>
   <data encoding="csv">
0,0,0,0,
6,0,0,7,
0,0,0,0
</data>
  </layer>
  <objectgroup id="4" name="spawns">
   <object id="1" name="start" type="spawn" x="8" y="16">
    <point/>
   </object>
  </objectgroup>
  <group id="5" name="inner" visible="0" opacity="0.5">
   <layer id="6" name="decor" width="4" height="3" opacity="0.5">
    <properties>
     <property name="collision" type="bool" value="false"/>
    </properties>
    <data encoding="csv">
0,0,0,0,
0,0,0,0,
1,2,3,0
</data>
   </layer>
  </group>
 </group>
 <imagelayer id="7" name="sky">
  <image source="images/sky.png" width="64" height="24"/>
 </imagelayer>
 <layer id="8" name="hidden" width="4" height="3" visible="0" opacity="0.25">
  <data encoding="csv">
0,0,0,0,
0,0,0,0,
0,0,0,3
</data>
 </layer>
 <objectgroup id="9" name="entities" color="#ff0000">
  <properties>
   <property name="spawn_layer" type="bool" value="true"/>
  </properties>
  <object id="1" name="player" type="player" x="16" y="32" width="16" height="16">
   <properties>
    <property name="speed" type="int" value="3"/>
    <property name="jump" type="float" value="15.5"/>
    <property name="can_fly" type="bool" value="false"/>
    <property name="label" value="Hero"/>
    <property name="bio">first line
second line</property>
    <property name="tint" type="color" value="#ff00ff00"/>
   </properties>
  </object>
  <object id="2" name="slime" class="enemy" x="40.5" y="8" width="12" height="10" rotation="90"/>
  <object id="3" name="crate" gid="2147483655" x="0" y="48" width="16" height="16" visible="0"/>
  <object id="4" name="zone" x="0" y="0" width="64" height="24">
   <ellipse/>
  </object>
  <object id="5" name="both" type="old" class="new" x="-8" y="-4.25"/>
  <gizmo kind="unknown"/>
 </objectgroup>
</map>
"""

# --- broken maps --------------------------------------------------------------
#
# small_map's layout, by line:
#   1 <?xml ...?>
#   2 <map ...>
#   3  <tileset .../>
#   4  <layer ...>
#   5   <data ...>...</data>
#   6  </layer>
#   7 </map>

TILESET_LINE = '<tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="8" columns="4"/>'


def small_map(data, map_attrs='orientation="orthogonal" width="2" height="2" tilewidth="16" tileheight="16"',
              tileset=TILESET_LINE, layer_attrs='width="2" height="2"'):
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<map version="1.10" {map_attrs}>\n'
            f' {tileset}\n'
            f' <layer id="1" name="ground" {layer_attrs}>\n'
            f'  {data}\n'
            f' </layer>\n'
            f'</map>\n')


def b64_data(gids, compression=None, payload=None):
    body = payload if payload is not None else b64(le_bytes(gids))
    comp = f' compression="{compression}"' if compression else ""
    return f'<data encoding="base64"{comp}>\n   {body}\n  </data>'


def bad_maps():
    ok = '<data encoding="csv">1,2,3,4</data>'
    four = le_bytes([1, 2, 3, 4])
    garbage = bytes(range(7, 40))
    maps = {
        "malformed.tmx": small_map('<data encoding="csv">1,2,3,4</dat>'),
        "no_map.tmx": '<?xml version="1.0"?>\n<tileset name="oops" tilewidth="16" tileheight="16"/>\n',
        "empty.tmx": "",
        "bad_encoding.tmx": small_map('<data encoding="base32">AAAA</data>'),
        "bad_compression.tmx": small_map(b64_data([1, 2, 3, 4], "lzma")),
        "bad_base64_char.tmx": small_map(b64_data(None, payload="AQAAAAIA!AAAAwAAAAQAAAA=")),
        "truncated_base64.tmx": small_map(b64_data(None, payload=b64(four)[:9])),
        "corrupt_zlib.tmx": small_map(b64_data(None, "zlib", b64(garbage))),
        "truncated_zlib.tmx": small_map(b64_data(None, "zlib", b64(zlib.compress(four)[:8]))),
        "corrupt_gzip.tmx": small_map(b64_data(None, "gzip", b64(b"\x1f\x8b\x08\x00" + garbage))),
        "corrupt_zstd.tmx": small_map(b64_data(None, "zstd", b64(b"\x28\xb5\x2f\xfd" + garbage))),
        "truncated_zstd.tmx": small_map(b64_data(None, "zstd", b64(zstd(four)[:-6]))),
        "short_csv.tmx": small_map('<data encoding="csv">1,2,3</data>'),
        "long_base64.tmx": small_map(b64_data([1, 2, 3, 4, 5])),
        "odd_base64.tmx": small_map(b64_data(None, payload=b64(four + b"\x01\x02"))),
        "long_zlib.tmx": small_map(b64_data(None, "zlib", b64(zlib.compress(le_bytes([1, 2, 3, 4, 5]))))),
        "short_xml.tmx": small_map('<data><tile gid="1"/><tile/></data>'),
        "bad_csv_value.tmx": small_map('<data encoding="csv">1,x7,3,4</data>'),
        "bad_tile_gid.tmx": small_map('<data><tile gid="1"/><tile gid="two"/><tile/><tile/></data>'),
        "csv_compressed.tmx": small_map('<data encoding="csv" compression="zlib">1,2,3,4</data>'),
        "no_data.tmx": small_map("<properties/>"),
        "missing_tsx.tmx": small_map(ok, tileset='<tileset firstgid="1" source="tilesets/missing.tsx"/>'),
        "malformed_tsx.tmx": small_map(ok, tileset='<tileset firstgid="1" source="tilesets/malformed.tsx"/>'),
        "bad_tsx_attr.tmx": small_map(ok, tileset='<tileset firstgid="1" source="tilesets/bad_attr.tsx"/>'),
        "gid_beyond.tmx": small_map(f'<data encoding="csv">1,{9 | H},0,0</data>'),
        "gid_below.tmx": small_map('<data encoding="csv">5,3,0,0</data>',
                                   tileset=TILESET_LINE.replace('firstgid="1"', 'firstgid="5"')),
        "no_tileset.tmx": small_map('<data encoding="csv">0,0,0,1</data>', tileset="<!-- none -->"),
        "bad_width.tmx": small_map(ok, map_attrs='orientation="orthogonal" width="six" height="2" tilewidth="16" tileheight="16"'),
        "bad_tilewidth.tmx": small_map(ok, map_attrs='orientation="orthogonal" width="2" height="2" tilewidth="16px" tileheight="16"'),
        "zero_tileheight.tmx": small_map(ok, map_attrs='orientation="orthogonal" width="2" height="2" tilewidth="16" tileheight="0"'),
        "missing_tilewidth.tmx": small_map(ok, map_attrs='orientation="orthogonal" width="2" height="2" tileheight="16"'),
        "bad_firstgid.tmx": small_map(ok, tileset=TILESET_LINE.replace('firstgid="1"', 'firstgid="one"')),
        "zero_firstgid.tmx": small_map(ok, tileset=TILESET_LINE.replace('firstgid="1"', 'firstgid="0"')),
        "bad_layer_height.tmx": small_map(ok, layer_attrs='width="2" height="-2"'),
        "isometric.tmx": small_map(ok, map_attrs='orientation="isometric" width="2" height="2" tilewidth="16" tileheight="16"'),
        "bad_chunk_x.tmx": small_map('<data encoding="csv"><chunk x="1.5" y="0" width="2" height="2">1,2,3,4</chunk></data>',
                                     map_attrs='orientation="orthogonal" width="2" height="2" tilewidth="16" tileheight="16" infinite="1"'),
        "short_chunk.tmx": small_map('<data encoding="csv">\n   <chunk x="-2" y="0" width="2" height="2">1,2,3</chunk>\n  </data>',
                                    map_attrs='orientation="orthogonal" width="2" height="2" tilewidth="16" tileheight="16" infinite="1"'),
        "huge_chunks.tmx": small_map('<data encoding="csv"><chunk x="-2000000000" y="0" width="1" height="1">1</chunk>'
                                     '<chunk x="2000000000" y="0" width="1" height="1">1</chunk></data>',
                                     map_attrs='orientation="orthogonal" width="2" height="2" tilewidth="16" tileheight="16" infinite="1"'),
        "bad_object_x.tmx": small_map(ok).replace(
            " </layer>\n", ' </layer>\n <objectgroup id="2" name="things">\n  <object id="1" x="left" y="0"/>\n </objectgroup>\n'),
    }
    for name, text in maps.items():
        write(os.path.join("bad", name), text)
    # malformed.tsx leaves the <image> of line 3 unclosed; tinyxml2 reports line 3.
    write("bad/tilesets/malformed.tsx",
          '<?xml version="1.0" encoding="UTF-8"?>\n'
          '<tileset name="broken" tilewidth="16" tileheight="16" tilecount="4" columns="2">\n'
          ' <image source="x.png" width="32" height="32">\n'
          '</tileset>\n')
    write("bad/tilesets/bad_attr.tsx",
          '<?xml version="1.0" encoding="UTF-8"?>\n'
          '<tileset name="broken" tilewidth="16" tileheight="16" tilecount="many" columns="2">\n'
          '</tileset>\n')


def main():
    write("tilesets/terrain.tsx", TERRAIN_TSX)
    for enc in ["csv", "base64", "zlib", "gzip", "zstd", "zstd_stream", "xml"]:
        write(f"level_{enc}.tmx", level_map(enc))
    write("infinite.tmx", INFINITE)
    write("tilesets.tmx", TILESETS)
    write("layers.tmx", LAYERS)
    bad_maps()


if __name__ == "__main__":
    main()
