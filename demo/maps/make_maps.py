#!/usr/bin/env python3
# SPDX-License-Identifier: 0BSD
"""Regenerates the Tiled maps of the demos (demo/*.scm) under demo/maps/
(all but level1.tmx, which demo/fall.scm and the tests load as it is).

The outputs are checked in; the build never runs this. Standard library only.
Run it from anywhere:
    python3 demo/maps/make_maps.py

Every map is orthogonal with 16x16 tiles and uses the external tileset
written here, demo-tiles.tsx (over tiles.png, 4 tiles in a row), then
sprites.tsx (written by make_art.py) for the entities' pictures. Solidity is
tile metadata: a <properties><property name="solid" type="bool" value="true"/>
on the tile. Levels are drawn below as ASCII, one character a cell:

    .  empty                         gid 0
    #  ground      (tile 0, solid)   gid 1
    W  wall        (tile 1, solid)   gid 2
    =  platform    (tile 2, solid)   gid 3
    "  grass/decor (tile 3, NOT solid: no "solid" property) gid 4
    -  one-way plank (level-tiles 0, "one-way" property)   gid 21
    B  breakable block (level-tiles 1, solid)              gid 22
    /  45° ramp up to the right (level-tiles 2, a collision triangle) gid 23
    a  1:2 ramp, lower tile (level-tiles 3)                gid 24
    b  1:2 ramp, upper tile (level-tiles 4)                gid 25
    \\  c  d   the same flipped horizontally: the way down

The layers are written in different encodings (CSV, base64, base64+zlib) so
the demos exercise the loader's paths too. Objects (spawn points, coins, the
goal) go in an object layer; the demos read them with tilemap-objects.
"""
import base64
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
TILE = 16
# sprites.tsx (16x16 frames, written by make_art.py) follows demo-tiles.tsx in
# every map, so that entities can take a #:sprite gid from the map's tilesets:
# (+ SPRITES_FIRSTGID local-id). No cell uses it.
SPRITES_FIRSTGID = 1 + 4  # demo-tiles.tsx's firstgid + its tilecount
# level-tiles.tsx (over level-tiles.png, also written by make_art.py) follows
# sprites.tsx in the platformer only, so the gids before it stay as they were:
# a one-way plank and a block the player breaks from below.
LEVEL_FIRSTGID = SPRITES_FIRSTGID + 16  # sprites.tsx's tilecount
FLIP_H = 0x80000000  # Tiled's horizontal flip bit on a gid
GIDS = {".": 0, "#": 1, "W": 2, "=": 3, '"': 4, "-": LEVEL_FIRSTGID, "B": LEVEL_FIRSTGID + 1,
        "/": LEVEL_FIRSTGID + 2, "a": LEVEL_FIRSTGID + 3, "b": LEVEL_FIRSTGID + 4,
        "\\": FLIP_H | (LEVEL_FIRSTGID + 2), "c": FLIP_H | (LEVEL_FIRSTGID + 4), "d": FLIP_H | (LEVEL_FIRSTGID + 3)}

TILESET = """<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.10.2" name="demo-tiles" tilewidth="16" tileheight="16" tilecount="4" columns="4">
 <image source="tiles.png" width="64" height="16"/>
 <tile id="0" type="ground">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1" type="wall">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="2" type="platform">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="3" type="decor">
  <properties>
   <property name="solid" type="bool" value="false"/>
  </properties>
 </tile>
</tileset>
"""

# ---------------------------------------------------------------- platformer
# 100x15. Ground top at row 11 (y 176); a pit at columns 30-35 two tiles deep
# (its floor's top at row 13, y 208) whose right side rises into a wall (column
# 36, rows 8-12: 80 px above the pit floor); two platforms (row 8, y 128; row
# 5, y 80); grass that is not solid; walls at both ends. Then a one-way plank
# (row 8, columns 62-67) to jump up through and drop down from, three blocks
# to break from below (row 8, columns 71-73), and a pit too wide to jump
# (columns 78-89, three tiles deep) that the "lift" object carries you over.
# Between the pit and the plank, a hill (columns 44-51): up a 1:2 ramp and a
# 45° ramp to a top two tiles wide (row 9, y 144), down a 45° and a 1:2 one.
PLATFORMER = [
    "W..................................................................................................W",  # 0
    "W..................................................................................................W",  # 1
    "W..................................................................................................W",  # 2
    "W..................................................................................................W",  # 3
    "W..................................................................................................W",  # 4
    "W...............====...............................................................................W",  # 5
    "W..................................................................................................W",  # 6
    "W..................................................................................................W",  # 7
    "W.........====......................W.........................------...BBB.........................W",  # 8
    "W...................................W........./##\\.................................................W",  # 9
    'W.."".................."............W.......ab####cd"........................................".....W',  # 10
    "W#############################......##########################################............#########W",  # 11
    "W#############################......##########################################............#########W",  # 12
    "W#############################################################################............#########W",  # 13
    "W##################################################################################################W",  # 14
]
PLATFORMER_OBJECTS = [
    ("player", "player", 40, 100, 12, 16, {}),
    ("goal", "goal", 1520, 144, 16, 32, {}),
    # A lift over the second pit, flush with the ground at both ends of its
    # run (x 1248 to 1392, its right end then at the far edge, 1440).
    ("lift", "lift", 1248, 176, 48, 8, {"to-x": 1392, "speed": 2}),
]

# ---------------------------------------------------------------- top-down
# 20x15 room: border walls, an inner wall (column 10, rows 1-8), a block of
# ground (columns 4-6, rows 10-11) and non-solid grass.
TOPDOWN = [
    "WWWWWWWWWWWWWWWWWWWW",  # 0
    "W.........W........W",  # 1
    "W.........W........W",  # 2
    "W.........W........W",  # 3
    "W.........W..\"\"....W",  # 4
    "W..\"\"\"....W........W",  # 5
    "W.........W........W",  # 6
    "W.........W........W",  # 7
    "W.........W........W",  # 8
    "W..................W",  # 9
    "W...###............W",  # 10
    "W...###.....\"\".....W",  # 11
    "W..................W",  # 12
    "W..................W",  # 13
    "WWWWWWWWWWWWWWWWWWWW",  # 14
]
TOPDOWN_OBJECTS = [
    ("player", "player", 40, 40, 12, 12, {"speed": 3}),
    ("coin1", "coin", 100, 44, 8, 8, {"value": 10}),
    ("coin2", "coin", 150, 120, 8, 8, {"value": 10}),
    ("coin3", "coin", 60, 214, 8, 8, {"value": 10}),
    ("coin4", "coin", 18, 100, 8, 8, {"value": 10}),
    ("coin5", "coin", 250, 150, 8, 8, {"value": 50}),
]

# ---------------------------------------------------------------- sandbox
# 30x15: border walls, floor top at row 13 (y 208), a stub wall (column 15,
# rows 11-12) that the bots turn at, and a tile ledge (row 7, columns 24-27,
# y 112). The immovable platforms, boxes, raft and bots are entities (in
# demo/sandbox.scm).
SANDBOX = [
    "WWWWWWWWWWWWWWWWWWWWWWWWWWWWWW",  # 0
    "W............................W",  # 1
    "W............................W",  # 2
    "W............................W",  # 3
    "W............................W",  # 4
    "W............................W",  # 5
    "W............................W",  # 6
    "W.......................====.W",  # 7
    "W............................W",  # 8
    "W............................W",  # 9
    "W............................W",  # 10
    "W..............W.............W",  # 11
    'W....""........W.......".....W',  # 12
    "W############################W",  # 13
    "W############################W",  # 14
]

# ---------------------------------------------------------------- shmup, tweens
# 20x15, the screen's size, and no tile at all: demo/shmup.scm and
# demo/tweens.scm load these only for the tilesets, so that their entities
# can take a #:sprite gid. A map with no solid cell adds no collision (tweens'
# engine-update steps tile collisions against it; shmup has no physics
# pass), and neither scene has a camera-target, so the map's size clamps no
# camera.
EMPTY_SCREEN = ["." * 20] * 15


def gids_of(rows):
    width = len(rows[0])
    assert all(len(r) == width for r in rows), "ragged map"
    return [GIDS[c] for row in rows for c in row], width, len(rows)


def data_element(gids, width, encoding):
    raw = b"".join(struct.pack("<I", g) for g in gids)
    if encoding == "csv":
        lines = [",".join(str(g) for g in gids[i:i + width]) for i in range(0, len(gids), width)]
        return '  <data encoding="csv">\n' + ",\n".join(lines) + "\n</data>"
    if encoding == "base64":
        return f'  <data encoding="base64">\n   {base64.b64encode(raw).decode()}\n  </data>'
    if encoding == "zlib":
        packed = base64.b64encode(zlib.compress(raw, 9)).decode()
        return f'  <data encoding="base64" compression="zlib">\n   {packed}\n  </data>'
    raise ValueError(encoding)


def prop_element(name, value):
    kind = "int" if isinstance(value, int) else "float" if isinstance(value, float) else "string"
    return f'    <property name="{name}" type="{kind}" value="{value}"/>'


def objects_element(objects, layer="spawns"):
    if not objects:
        return ""
    out = [f' <objectgroup id="2" name="{layer}">']
    for i, (name, kind, x, y, w, h, props) in enumerate(objects, 1):
        head = f'  <object id="{i}" name="{name}" type="{kind}" x="{x}" y="{y}" width="{w}" height="{h}"'
        if props:
            out.append(head + ">")
            out.append("   <properties>")
            out.extend(prop_element(k, v) for k, v in props.items())
            out.append("   </properties>")
            out.append("  </object>")
        else:
            out.append(head + "/>")
    out.append(" </objectgroup>")
    return "\n".join(out) + "\n"


# level-tiles 2-4: the hill's ramps, each a collision polygon (semantics §12):
# 45°, and the lower and upper tiles of a 1:2 ramp, all rising to the right.
RAMPS = {2: "0,16 16,16 16,0", 3: "0,16 16,16 16,8", 4: "0,16 16,16 16,0 0,8"}
RAMP_TILE = """ <tile id="{id}" type="ramp">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="{points}"/>
   </object>
  </objectgroup>
 </tile>
"""

LEVEL_TILESET = """<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.10.2" name="level-tiles" tilewidth="16" tileheight="16" tilecount="5" columns="5">
 <image source="level-tiles.png" width="80" height="16"/>
 <tile id="0" type="one-way">
  <properties>
   <property name="one-way" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1" type="breakable">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
{ramp_tiles}</tileset>
"""


# The platformer's layers around its level: a far backdrop (an image layer
# repeated along x, scrolling at a third of the camera's speed) under it,
# and grass in front: a tile layer after the object layer the entities are
# drawn in (the map property entity-layer names it), so the player walks
# behind the tufts. Grass never collides (tile 3 is not solid).
BACKDROP = """ <imagelayer id="3" name="backdrop" repeatx="1" parallaxx="0.33" parallaxy="1">
  <image source="backdrop.png" width="192" height="240"/>
 </imagelayer>
"""
FRONT_GRASS_COLUMNS = [6, 7, 8, 17, 18, 27, 28, 40, 41, 60, 61, 62, 95, 96]


def front_layer(rows, width, height, encoding):
    gids = [0] * (width * height)
    for col in FRONT_GRASS_COLUMNS:
        row = next(r for r in range(height) if rows[r][col] == "#") - 1
        assert rows[row][col] == ".", f"front grass at column {col} would cover a tile"
        gids[row * width + col] = GIDS['"']
    return (f' <layer id="4" name="front" width="{width}" height="{height}">\n'
            f'{data_element(gids, width, encoding)}\n </layer>\n')


def tmx(rows, encoding, objects=(), title="", level_tiles=False, scenery=False):
    gids, width, height = gids_of(rows)
    level_tileset = f' <tileset firstgid="{LEVEL_FIRSTGID}" source="level-tiles.tsx"/>\n' if level_tiles else ""
    entity_layer = '  <property name="entity-layer" value="spawns"/>\n' if scenery else ""
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" width="{width}" height="{height}" tilewidth="{TILE}" tileheight="{TILE}" infinite="0" nextlayerid="{5 if scenery else 3}" nextobjectid="{len(objects) + 1}">
 <properties>
{entity_layer}  <property name="title" value="{title}"/>
 </properties>
 <tileset firstgid="1" source="demo-tiles.tsx"/>
 <tileset firstgid="{SPRITES_FIRSTGID}" source="sprites.tsx"/>
{level_tileset}{BACKDROP if scenery else ""} <layer id="1" name="tiles" width="{width}" height="{height}">
{data_element(gids, width, encoding)}
 </layer>
{objects_element(objects)}{front_layer(rows, width, height, encoding) if scenery else ""}</map>
"""


def write(name, text):
    with open(os.path.join(HERE, name), "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


def main():
    write("demo-tiles.tsx", TILESET)
    write("level-tiles.tsx", LEVEL_TILESET.replace(
        "{ramp_tiles}", "".join(RAMP_TILE.format(id=i, points=p) for i, p in RAMPS.items())))
    write("platformer.tmx", tmx(PLATFORMER, "csv", PLATFORMER_OBJECTS, "platformer", level_tiles=True,
                                scenery=True))
    write("topdown.tmx", tmx(TOPDOWN, "base64", TOPDOWN_OBJECTS, "top-down"))
    write("sandbox.tmx", tmx(SANDBOX, "zlib", (), "sandbox"))
    write("shmup.tmx", tmx(EMPTY_SCREEN, "csv", (), "shmup"))
    write("tweens.tmx", tmx(EMPTY_SCREEN, "csv", (), "tweens"))


if __name__ == "__main__":
    main()
