#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates tests/data/maps/features/, the small maps of the TMX features
tests/core/tmx_features_test.cpp checks with exact values: object shapes,
templates, class and list properties, the layer tree, tileset extras, gids
beyond every tileset, sparse image collections and text encodings.

The outputs are checked in; the build never runs this. Layouts are fixed so
the tests can assert line numbers. Run it from anywhere:
    python3 tests/data/make_feature_maps.py
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "maps", "features")

HEAD = '<?xml version="1.0" encoding="UTF-8"?>\n'
MAP = ('<map version="1.10" orientation="orthogonal" width="{w}" height="{h}" '
       'tilewidth="16" tileheight="16" infinite="0"{extra}>\n')
TERRAIN = ' <tileset firstgid="1" source="../tilesets/terrain.tsx"/>\n'


def write(rel, data):
    path = os.path.join(OUT, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if isinstance(data, str):
        data = data.encode("utf-8")
    with open(path, "wb") as f:
        f.write(data)


def tile_layer(name, w, csv, extra=""):
    return (f' <layer id="1" name="{name}" width="{w}" height="{len(csv) // w}"{extra}>\n'
            f'  <data encoding="csv">{",".join(str(g) for g in csv)}</data>\n'
            ' </layer>\n')


OBJECTS = HEAD + MAP.format(w=2, h=2, extra="") + TERRAIN + tile_layer("ground", 2, [0, 0, 0, 0]) + """\
 <objectgroup id="2" name="things">
  <object id="1" name="box" type="crate" x="1" y="2" width="3" height="4"/>
  <object id="2" name="oval" x="5" y="6" width="7" height="8" rotation="45">
   <ellipse/>
  </object>
  <object id="3" name="spot" x="9" y="10" visible="0">
   <point/>
  </object>
  <object id="4" name="tri" x="11" y="12">
   <polygon points="0,0 10.5,0 -2,-3.25"/>
  </object>
  <object id="5" name="path" x="13" y="14">
   <polyline points="0,0 4,4"/>
  </object>
  <object id="6" name="sign" x="15" y="16" width="80" height="20">
   <text fontfamily="Serif" pixelsize="12" wrap="1" bold="1" color="#ff0000" halign="center" valign="bottom">Hello
there</text>
  </object>
  <object id="7" name="tile" gid="2684354563" x="17" y="18" width="16" height="16"/>
 </objectgroup>
</map>
"""

# A tile-object template counted in terrain.tsx as the map counts it, and
# an ellipse template with properties.
CRATE_TX = HEAD + """<template>
 <tileset firstgid="1" source="../../tilesets/terrain.tsx"/>
 <object name="crate" type="pickup" gid="2147483652" width="16" height="16">
  <properties>
   <property name="weight" type="int" value="3"/>
  </properties>
 </object>
</template>
"""
SPAWN_TX = HEAD + """<template>
 <object name="spawn" type="spawner" width="20" height="10" rotation="15">
  <properties>
   <property name="kind" value="bat"/>
   <property name="count" type="int" value="2"/>
  </properties>
  <ellipse/>
 </object>
</template>
"""
# Its object names a template: templates do not nest, this is not followed.
SELF_TX = HEAD + """<template>
 <object name="self" template="self.tx" width="1" height="1"/>
</template>
"""

TEMPLATES = HEAD + MAP.format(w=2, h=2, extra="") + """\
 <tileset firstgid="1" source="../tilesets/terrain.tsx"/>
 <tileset firstgid="9" name="shapes" tilewidth="16" tileheight="16" tilecount="1" columns="1">
  <image source="shapes.png" width="16" height="16"/>
  <tile id="0">
   <objectgroup>
    <object id="1" template="templates/spawn.tx" x="2" y="3"/>
   </objectgroup>
  </tile>
 </tileset>
""" + tile_layer("ground", 2, [0, 0, 0, 0]) + """\
 <objectgroup id="2" name="things">
  <object id="1" template="templates/spawn.tx" x="100" y="50">
   <properties>
    <property name="count" type="int" value="5"/>
    <property name="boss" type="bool" value="true"/>
   </properties>
  </object>
  <object id="2" template="templates/spawn.tx" name="big" x="1" y="2" width="40" visible="0"/>
  <object id="3" template="templates/crate.tx" x="30" y="40"/>
  <object id="4" template="templates/spawn.tx" x="0" y="0">
   <point/>
  </object>
  <object id="5" template="templates/self.tx" x="7" y="8"/>
 </objectgroup>
</map>
"""

# A template that says where it is: Tiled never places an instance there.
PLACED_TX = HEAD + """<template>
 <object name="placed" type="marker" x="70" y="80" width="20" height="10" rotation="30" visible="0">
  <properties>
   <property name="a" value="template"/>
   <property name="b" type="int" value="1"/>
  </properties>
  <ellipse/>
 </object>
</template>
"""

# Instances that write what Tiled does not take as an override (an empty
# name or class, a size with a side of 0, gid 0) and what it does (rotation
# and visible, whatever their values).
TEMPLATE_RULES = HEAD + MAP.format(w=2, h=2, extra="") + TERRAIN + tile_layer("ground", 2, [0, 0, 0, 0]) + """\
 <objectgroup id="2" name="things">
  <object id="1" template="templates/placed.tx" name="" type="" x="5" y="6" width="0" height="30"/>
  <object id="2" template="templates/placed.tx"/>
  <object id="3" template="templates/placed.tx" x="1" y="2" width="8" height="0"/>
  <object id="4" template="templates/placed.tx" name="own" class="mine" x="3" y="4" width="8" height="6" rotation="0" visible="1" gid="0">
   <properties>
    <property name="b" type="int" value="2"/>
    <property name="c" value="instance"/>
   </properties>
  </object>
 </objectgroup>
</map>
"""

# The map lacks the template's tileset: it is added after the last firstgid.
TEMPLATE_ADDS_TILESET = HEAD + MAP.format(w=2, h=2, extra="") + """\
 <tileset firstgid="1" name="one" tilewidth="16" tileheight="16" tilecount="3" columns="3">
  <image source="one.png" width="48" height="16"/>
 </tileset>
""" + tile_layer("ground", 2, [1, 0, 0, 0]) + """\
 <objectgroup id="2" name="things">
  <object id="1" template="templates/crate.tx" x="30" y="40"/>
 </objectgroup>
</map>
"""

MISSING_TEMPLATE = HEAD + MAP.format(w=2, h=2, extra="") + TERRAIN + tile_layer("ground", 2, [0, 0, 0, 0]) + """\
 <objectgroup id="2" name="things">
  <object id="1" template="templates/nowhere.tx" x="1" y="1"/>
 </objectgroup>
</map>
"""

DEV_ZERO_TEMPLATE = MISSING_TEMPLATE.replace("templates/nowhere.tx", "/dev/zero")

PROPERTIES = HEAD + MAP.format(w=2, h=2, extra="") + """\
 <properties>
  <property name="spawn" type="class" propertytype="Spawn">
   <properties>
    <property name="hp" type="int" value="3"/>
    <property name="pos" type="class" propertytype="Point">
     <properties>
      <property name="x" type="float" value="1.5"/>
     </properties>
    </property>
   </properties>
  </property>
  <property name="empty" type="class" propertytype="Nothing"/>
  <property name="path" type="list">
   <item type="int" value="4"/>
   <item type="string" value="two"/>
   <item type="class" propertytype="Point">
    <properties>
     <property name="y" type="float" value="-2"/>
    </properties>
   </item>
  </property>
  <property name="poem" type="string">roses
are red</property>
  <property name="mood" type="int" propertytype="Mood" value="2"/>
  <property name="name" value="custom"/>
 </properties>
""" + TERRAIN + tile_layer("ground", 2, [0, 0, 0, 0]) + "</map>\n"


def deep_class(depth):
    inner = '<property name="leaf" value="x"/>'
    for i in range(depth):
        inner = (f'<property name="c{i}" type="class" propertytype="C">'
                 f'<properties>{inner}</properties></property>')
    return (HEAD + MAP.format(w=2, h=2, extra="") +
            f" <properties>{inner}</properties>\n" + TERRAIN +
            tile_layer("ground", 2, [0, 0, 0, 0]) + "</map>\n")


LAYERS = HEAD + MAP.format(w=2, h=2, extra=' class="level" backgroundcolor="#ff336699"') + """\
 <tileset firstgid="1" name="anim" class="water" tilewidth="16" tileheight="16" tilecount="4" columns="4">
  <tileoffset x="3" y="-4"/>
  <properties>
   <property name="biome" value="sea"/>
  </properties>
  <image source="anim.png" width="64" height="16"/>
  <tile id="1">
   <animation>
    <frame tileid="1" duration="100"/>
    <frame tileid="2" duration="250"/>
   </animation>
  </tile>
 </tileset>
 <group id="10" name="world" class="zone" offsetx="10" offsety="5" opacity="0.5" parallaxx="0.5" parallaxy="0.25" tintcolor="#80ff0000">
  <properties>
   <property name="depth" type="int" value="1"/>
  </properties>
  <layer id="1" name="ground" width="2" height="2" offsetx="1" offsety="2" opacity="0.5">
   <data encoding="csv">1,2,0,0</data>
  </layer>
  <objectgroup id="2" name="things"/>
  <group id="11" name="inner" visible="0" offsetx="100">
   <imagelayer id="3" name="sky" repeatx="1">
    <image source="sky.png" width="320" height="200"/>
   </imagelayer>
   <layer id="4" name="deco" width="2" height="2">
    <data encoding="csv">0,0,0,3</data>
   </layer>
  </group>
 </group>
 <layer id="5" name="top" width="2" height="2">
  <data encoding="csv">0,0,0,0</data>
 </layer>
</map>
"""

# Gids 9 and 12 are past terrain.tsx's 8 tiles; cell (1, 0) is the first.
MISSING_GIDS = HEAD + MAP.format(w=3, h=2, extra="") + TERRAIN + \
    tile_layer("ground", 3, [1, 9, 0, 12, 2147483657, 0]) + \
    tile_layer("clean", 3, [1, 0, 0, 0, 0, 0]).replace('id="1"', 'id="2"') + \
    """ <layer id="3" name="walls" width="3" height="2">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
  <data encoding="csv">0,0,10,0,0,0</data>
 </layer>
</map>
"""

# An image collection whose tile ids have gaps and pass tilecount: Tiled
# keeps the ids of deleted tiles unused.
SPARSE = HEAD + MAP.format(w=3, h=1, extra="") + """\
 <tileset firstgid="1" name="pics" tilewidth="32" tileheight="32" tilecount="2" columns="0">
  <tile id="0">
   <image source="a.png" width="32" height="32"/>
  </tile>
  <tile id="5">
   <properties>
    <property name="solid" type="bool" value="true"/>
   </properties>
   <image source="f.png" width="32" height="32"/>
  </tile>
 </tileset>
""" + tile_layer("ground", 3, [1, 6, 3]) + "</map>\n"


def text_map(encoding_decl, value):
    return (f'<?xml version="1.0" encoding="{encoding_decl}"?>\n' +
            MAP.format(w=2, h=2, extra="") +
            f' <properties>\n  <property name="word" value="{value}"/>\n </properties>\n' +
            TERRAIN + tile_layer("ground", 2, [0, 0, 0, 0]) + "</map>\n")


def main():
    write("objects.tmx", OBJECTS)
    write("templates/crate.tx", CRATE_TX)
    write("templates/spawn.tx", SPAWN_TX)
    write("templates/self.tx", SELF_TX)
    write("templates.tmx", TEMPLATES)
    write("templates/placed.tx", PLACED_TX)
    write("template_rules.tmx", TEMPLATE_RULES)
    write("template_adds_tileset.tmx", TEMPLATE_ADDS_TILESET)
    write("missing_template.tmx", MISSING_TEMPLATE)
    write("dev_zero_template.tmx", DEV_ZERO_TEMPLATE)
    write("properties.tmx", PROPERTIES)
    write("deep_class.tmx", deep_class(40))
    write("layers.tmx", LAYERS)
    write("missing_gids.tmx", MISSING_GIDS)
    write("sparse_collection.tmx", SPARSE)
    write("latin1.tmx", text_map("ISO-8859-1", "café").encode("iso-8859-1"))
    write("windows1252.tmx", text_map("windows-1252", "5€").encode("cp1252"))
    write("utf16.tmx", text_map("UTF-16", "naïve").encode("utf-16"))  # with a BOM
    write("unknown_encoding.tmx", text_map("KLINGON-8", "x"))
    # A stray Latin-1 é in a UTF-8 file, on line 4.
    write("bad_byte.tmx", text_map("UTF-8", "caf\x00").encode("utf-8").replace(b"\x00", b"\xe9"))
    # 0x81 has no character in windows-1252.
    write("bad_cp1252.tmx", text_map("windows-1252", "x\x00").encode("cp1252").replace(b"\x00", b"\x81"))


if __name__ == "__main__":
    main()
