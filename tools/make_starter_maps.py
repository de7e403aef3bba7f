#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the starter game's tileset and map (templates/starter/maps/, what
`downstroke new' copies) and the tutorial game's maps (demo/tutorial/maps/).

The outputs are checked in; the build never runs this. Standard library only.
Run it from anywhere:
    python3 tools/make_starter_maps.py

The pictures are demo/maps/make_art.py's (imported from there), plus a door
drawn here; they go into ONE tileset, tiles.tsx over tiles.png, so that a new
author meets one file of art. Its local ids (gid = id + 1 in every map):

    0 ground       solid            6 player
    1 wall         solid            7 player-run
    2 plank        one-way          8 player-jump
    3 grass        not solid        9 coin
    4 door-top     not solid       10 walker
    5 door-bottom  not solid       11 walker-step

Levels are drawn below as ASCII, one character a cell:

    .  empty        #  ground      W  wall       -  one-way plank
    ,  grass        T  door's top  D  door's bottom (and the door object)
    p  the player's spawn point    c  a coin     e  an enemy (a walker)

The letters p, c, e and D become objects of the layer "things" (class
player, coin, enemy, door), which the games read with tilemap-objects; the
cells under p, c and e stay empty. Objects are rectangles: the game draws
what they become, and Tiled shows each with its class and name.
"""
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TILE = 16

def demo_script(name):
    """demo/maps/NAME.py, whose pictures and map-writing pieces are used here."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(ROOT, "demo", "maps", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


art = demo_script("make_art")
maps = demo_script("make_maps")

DOOR_TOP = [  # an arched wooden door, two cells tall: the upper half
    "................",
    "......kkkk......",
    "....kknnnnkk....",
    "...knnoooonnk...",
    "..knooottoooonk.",
    "..knottttttoonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
]
DOOR_BOTTOM = [  # the lower half, with its ring handle, on a stone step
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnkkonk.",
    ".knottnttkYYknk.",
    ".knottnttkYdknk.",
    ".knottnttnkkonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knottnttnttonk.",
    ".knnnnnnnnnnnnk.",
    "kk222222222222kk",
    "k33333333333333k",
    "kkkkkkkkkkkkkkkk",
]

# (name, picture, properties): a tile's local id is its index here.
TILES = [
    ("ground", art.GROUND, {"solid": True}),
    ("wall", art.WALL, {"solid": True}),
    ("plank", art.ONE_WAY, {"one-way": True}),
    ("grass", art.DECOR, {}),
    ("door-top", DOOR_TOP, {}),
    ("door-bottom", DOOR_BOTTOM, {}),
    ("player", art.PLAYER, {}),
    ("player-run", art.PLAYER_RUN, {}),
    ("player-jump", art.PLAYER_JUMP, {}),
    ("coin", art.COIN, {}),
    ("walker", art.WALKER, {}),
    ("walker-step", art.WALKER_STEP, {}),
]
COLUMNS = 6
GIDS = {".": 0, "#": 1, "W": 2, "-": 3, ",": 4, "T": 5, "D": 6}
# Each object letter: (class, width, height) of its rectangle, which sits on
# the bottom of its cell, centred across it.
OBJECTS = {"p": ("player", 12, 16), "c": ("coin", 8, 8), "e": ("enemy", 12, 14)}
# Custom properties each object of a class carries (Tiled: the object's
# Custom Properties): how far an enemy walks either way of where it starts.
OBJECT_PROPERTIES = {"enemy": {"patrol": 40}}
BACKGROUND = "#5c7cb8"  # a daytime sky behind everything

STARTER = [
    "W......................................W",
    "W......................................W",
    "W......................................W",
    "W......................................W",
    "W......................................W",
    "W......................................W",
    "W......................................W",
    "W......................................W",
    "W........................c.............W",
    "W.......................WWW............W",
    "W.................c....................W",
    "W................WWW...................W",
    "W......................................W",
    "Wp.....,,...c......,,.............c...,W",
    "########################################",
]

TUTORIAL_1 = [
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..................................c...............W",
    "W................................-----.............W",
    "W..........c.......................................W",
    "W.........---..........c...........................W",
    "W.....................WWW..........................W",
    "W......c...........................................W",
    "W..................................................W",
    "W...........................................c...T..W",
    "Wp....,,........e..........,,......e..........,,D..W",
    "####################################################",
]

TUTORIAL_2 = [
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..................................................W",
    "W..........................c.......................W",
    "W........................-----.....................W",
    "W..................................................W",
    "W.................c.....................c..........W",
    "W................---...................---.........W",
    "W.........c..............e.........................W",
    "W........WWW...........WWWWW.......................W",
    "W.................................................TW",
    "Wp......................e................e........DW",
    "####################################################",
]


def tileset_tsx():
    lines = art.tsx_head("tiles", len(TILES), COLUMNS)
    for i, (name, _, props) in enumerate(TILES):
        if not props:
            lines.append(f' <tile id="{i}" type="{name}"/>')
            continue
        lines.append(f' <tile id="{i}" type="{name}">')
        lines.append('  <properties>')
        lines += [f'   <property name="{k}" type="bool" value="{str(v).lower()}"/>' for k, v in props.items()]
        lines.append('  </properties>')
        lines.append(' </tile>')
    lines.append("</tileset>")
    return "\n".join(lines) + "\n"


def level_tmx(rows, title, door_to=None):
    """A map of ROWS; DOOR_TO, when given, is the door's property `to' (the
    map it leads to)."""
    height, width = len(rows), len(rows[0])
    for y, row in enumerate(rows):
        assert len(row) == width, f"{title} row {y}: {len(row)} cells, not {width}"
    gids, objects, counts = [], [], {}

    def add(kind, x, y, w, h, props):
        counts[kind] = counts.get(kind, 0) + 1
        name = kind if kind in ("player", "door") else f"{kind}-{counts[kind]}"
        objects.append((name, kind, x, y, w, h, props))

    for y, row in enumerate(rows):
        for x, c in enumerate(row):
            if c in OBJECTS:
                kind, w, h = OBJECTS[c]
                add(kind, x * TILE + (TILE - w) // 2, (y + 1) * TILE - h, w, h, dict(OBJECT_PROPERTIES.get(kind, {})))
                gids.append(0)
                continue
            gids.append(GIDS[c])
            if c == "D":  # the door: the two cells of its picture, T above D
                add("door", x * TILE, (y - 1) * TILE, TILE, 2 * TILE, {"to": door_to} if door_to else {})
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" renderorder="right-down" width="{width}" height="{height}" tilewidth="{TILE}" tileheight="{TILE}" infinite="0" backgroundcolor="{BACKGROUND}" nextlayerid="3" nextobjectid="{len(objects) + 1}">
 <properties>
  <property name="title" value="{title}"/>
 </properties>
 <tileset firstgid="1" source="tiles.tsx"/>
 <layer id="1" name="tiles" width="{width}" height="{height}">
{maps.data_element(gids, width, "csv")}
 </layer>
{maps.objects_element(objects, "things")}</map>
"""


def write_set(folder, maps):
    os.makedirs(folder, exist_ok=True)
    art.write(os.path.join(folder, "tiles.png"), art.png(art.sheet([p for _, p, _ in TILES], COLUMNS)))
    art.write(os.path.join(folder, "tiles.tsx"), tileset_tsx())
    for name, text in maps:
        art.write(os.path.join(folder, name), text)


def main(argv):
    for name, picture, _ in TILES:
        art.check(name, picture)
    write_set(os.path.join(ROOT, "templates", "starter", "maps"),
              [("level.tmx", level_tmx(STARTER, "starter"))])
    write_set(os.path.join(ROOT, "demo", "tutorial", "maps"),
              [("level1.tmx", level_tmx(TUTORIAL_1, "Level 1", door_to="level2.tmx")),
               ("level2.tmx", level_tmx(TUTORIAL_2, "Level 2"))])
    if len(argv) != 1:
        sys.exit(f"usage: {argv[0]}")


if __name__ == "__main__":
    main(sys.argv)
