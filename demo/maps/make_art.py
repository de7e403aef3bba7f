#!/usr/bin/env python3
# SPDX-License-Identifier: 0BSD
"""Draws the demos' pixel art and writes it under demo/maps/.

The outputs are checked in; the build never runs this. Standard library only
(zlib, struct). Run it from anywhere:
    python3 demo/maps/make_art.py                 # tiles.png, level-tiles.png, sprites.png, sprites.tsx
    python3 demo/maps/make_art.py --preview DIR   # also x8 enlargements, in DIR

Every picture is 16x16 and written below as 16 strings, one character a
pixel, looked up in PALETTE ('.' is transparent). Keeping the art as text
means a change to a sprite is a readable diff and needs no image editor.

tiles.png is the picture of tiles.tsx and demo-tiles.tsx: 4 tiles in a row,
local ids 0 ground, 1 wall, 2 platform, 3 decor. Those ids and their solidity
live in the .tsx files; only the picture is drawn here.

sprites.png is a sheet of 16x16 frames, 8 a row, described by sprites.tsx
(written here too), each frame with a type naming it. The renderer draws an
entity's #:sprite centred on its box horizontally and with the bottoms
aligned, so each sprite stands on its frame's bottom row and is sized to the
box the demos give that thing (a 12x12 box: columns 2-13, rows 4-15; the 2x6
bullet: columns 7-8, rows 10-15). Characters face right; the engine mirrors
them for left.
"""
import math
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
TILE = 16
SHEET_COLUMNS = 8

# One palette for everything, so the tiles and the sprites look like one game.
# Ramps go dark to light; 'k' is the outline of every character.
PALETTE = {
    ".": (0, 0, 0, 0),
    "k": (22, 17, 31),     # outline: near-black purple
    # greys / steel
    "1": (48, 47, 66),
    "2": (86, 88, 112),
    "3": (138, 144, 166),
    "4": (196, 204, 218),
    "w": (248, 248, 238),
    # earth and wood
    "b": (56, 34, 32),
    "n": (98, 58, 42),
    "o": (146, 92, 56),
    "t": (196, 136, 80),
    "y": (232, 188, 124),
    # grass and leaves
    "g": (34, 88, 58),
    "G": (58, 146, 62),
    "l": (118, 196, 78),
    "L": (188, 234, 118),
    # bricks
    "M": (64, 44, 54),     # mortar
    "q": (112, 44, 48),
    "Q": (160, 68, 60),
    "e": (202, 104, 78),
    # reds
    "r": (128, 28, 44),
    "R": (212, 52, 52),
    "p": (250, 128, 112),
    # golds and flame
    "d": (178, 106, 26),
    "Y": (244, 188, 44),
    "Z": (255, 238, 150),
    "f": (240, 120, 32),
    # blues
    "c": (34, 52, 118),
    "B": (52, 104, 206),
    "C": (96, 172, 240),
    "i": (184, 228, 255),
    # skin
    "S": (192, 118, 88),
    "s": (246, 186, 138),
    # purples
    "v": (84, 38, 110),
    "V": (146, 70, 176),
    "m": (214, 138, 232),
}

# ---------------------------------------------------------------- tiles.png
GROUND = [  # earth with a grassy top; repeats seamlessly left-right
    "LlLLlLLLlLLlLLLl",
    "lGllGllGlGlllGlG",
    "GGgGGGGgGGGGgGGG",
    "gGggGgggGgGgggGg",
    "ngngngnngnggngng",
    "nonnnonnnnonnnon",
    "oootooooooooooto",
    "oooooooonooooooo",
    "onooooooooootooo",
    "ooo23ooooooonooo",
    "oo2233oootoooooo",
    "ooo22ooooooooono",
    "otooooonooo23ooo",
    "ooooooooooo22noo",
    "oooonooootoooooo",
    "nooooooooooooooo",
]

WALL = [  # bricks in offset courses; repeats seamlessly both ways
    "eeeeeeQMeeeeeeQM",
    "eQQQQQqMeQQQeQqM",
    "QqqqqqqMQqqqqqqM",
    "MMMMMMMMMMMMMMMM",
    "eeQMeeeeeeQMeeee",
    "QqQMeQQQQQqMeQQQ",
    "qqqMQqqqqqqMQqqq",
    "MMMMMMMMMMMMMMMM",
    "eeeeeeQMeeeeeeQM",
    "eQQeQQqMeQQQQQqM",
    "QqqqqqqMQqqqqqqM",
    "MMMMMMMMMMMMMMMM",
    "eeQMeeeeeeQMeeee",
    "QqQMeQQQQQqMeQeQ",
    "qqqMQqqqqqqMQqqq",
    "MMMMMMMMMMMMMMMM",
]

PLATFORM = [  # a plank on a truss: the whole cell is solid, so it looks it
    "yyyyyyyyyyyyyyyy",
    "tttttttttttttttt",
    "t3ttottttttot3tt",
    "oooooooonooooooo",
    "nnnnnnnnnnnnnnnn",
    "bbbbbbbbbbbbbbbb",
    "oob..........boo",
    "nooob......boooo",
    "..nooob..booon..",
    "....noooooon....",
    "....booooooob...",
    "..booon..noooob.",
    "boooon....noooob",
    "oooon......noooo",
    "oooooooooooooooo",
    "nnnnnnnnnnnnnnnn",
]

DECOR = [  # a flower in a tuft of grass, not solid
    "................",
    "................",
    "................",
    ".......kkk......",
    "......kpppk.....",
    ".....kppYppk....",
    ".....kpYZYpk....",
    ".....krpYprk....",
    "......krrrk.....",
    ".......kGk......",
    "...k...kGk..k...",
    "..kGk..kGk.klk..",
    "..kGlk.kGkklGk..",
    "...kGlkkGklGk...",
    "...kgGlGGGGgk...",
    "..kgGGgGlgGGgk..",
]

TILES = [GROUND, WALL, PLATFORM, DECOR]

# ---------------------------------------------------------------- level-tiles.png
# level-tiles.tsx (written by make_maps.py): local ids 0 one-way plank,
# 1 breakable block. Only the platformer uses them.
ONE_WAY = [  # a thin plank on two brackets: you stand on its top, jump through it
    "yyyyyyyyyyyyyyyy",
    "tttttttttttttttt",
    "ottotttottotttto",
    "nnnnnnnnnnnnnnnn",
    "bbbbbbbbbbbbbbbb",
    ".kb..........bk.",
    "..kb........bk..",
    "...k........k...",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
]

BREAKABLE = [  # a riveted crate with a crack: it breaks when hit from below
    "kkkkkkkkkkkkkkkk",
    "kYZZZZZZZZZZZZYk",
    "kZdYYYYYYYYYYdZk",
    "kZYddddkdddddYZk",
    "kZYdYYYkYYYYdYZk",
    "kZYdYYkYYYYYdYZk",
    "kZYdYYkkYYYYdYZk",
    "kZYdYYYYkYYYdYZk",
    "kZYdYYYYkkYYdYZk",
    "kZYdYYYYYkYYdYZk",
    "kZYdYYYYkYYYdYZk",
    "kZYdYYYkYYYYdYZk",
    "kZYddddkdddddYZk",
    "kZdYYYYYYYYYYdZk",
    "kdddddddddddddYk",
    "kkkkkkkkkkkkkkkk",
]

def ramp(left, right):
    """A ramp of ground whose slope runs from height LEFT at the tile's left
    edge to RIGHT at its right edge (px from the tile's top), the ground
    picture below it, grass along it, nothing above: drawn as the collision
    polygon make_maps.py gives the tile, so it looks as it collides."""
    rows = []
    for y in range(TILE):
        row = ""
        for x in range(TILE):
            surface = left + (right - left) * (x + 0.5) / TILE
            depth = int(y + 0.5 - surface) if y + 0.5 >= surface else -1
            row += "." if depth < 0 else GROUND[min(depth, TILE - 1)][x]
        rows.append(row)
    return rows


# level-tiles.tsx local ids 2-4: the hill's ramps (45°, and the lower and
# upper tiles of a 1:2 ramp), rising to the right; the map flips them for
# the way down.
RAMP_45 = ramp(16, 0)
RAMP_12_LOW = ramp(16, 8)
RAMP_12_HIGH = ramp(8, 0)

LEVEL_TILES = [ONE_WAY, BREAKABLE, RAMP_45, RAMP_12_LOW, RAMP_12_HIGH]

# ---------------------------------------------------------------- sprites.png
# (type, picture); a sprite's local id is its index here.
PLAYER = [  # 12x16 box: columns 2-13
    "................",
    ".....kkkkk......",
    "....kBBCCBk.....",
    "...kBBBBCCBk....",
    "...kcBBBBBBBkk..",
    "...knnkkkkkkkkk.",
    "...knsssskssk...",
    "...knssssksssk..",
    "....kSsssssssk..",
    ".....kkSsskkk...",
    "....kfffYYfk....",
    "...kdffffYffk...",
    "...ksdffffdsk...",
    "....kccccccck...",
    "....kcck.kcck...",
    "...knnnk.knnnk..",
]

PLAYER_RUN = [
    "................",
    ".....kkkkk......",
    "....kBBCCBk.....",
    "...kBBBBCCBk....",
    "...kcBBBBBBBkk..",
    "...knnkkkkkkkkk.",
    "...knsssskssk...",
    "...knssssksssk..",
    "....kSsssssssk..",
    ".....kkSsskkk...",
    "....kfffYYfkk...",
    "...kdffffYffsk..",
    "..ksdffffffkk...",
    "...kccccckcck...",
    "..kcckk..kccck..",
    ".knnk.....knnnk.",
]

PLAYER_JUMP = [
    ".............k..",
    ".....kkkkk..ksk.",
    "....kBBCCBk.ksk.",
    "...kBBBBCCBkkfk.",
    "...kcBBBBBBBkfk.",
    "...knnkkkkkkkfk.",
    "...knsssskssfk..",
    "...knssssksffk..",
    "....kSsssssffk..",
    ".....kkSssYfk...",
    "....kfffYYfk....",
    "..kskdfffYfk....",
    "..kskddffffk....",
    "...kccccccccck..",
    "..knnk...kcnnk..",
    "...kk.....kkk...",
]

WALKER = [  # 12x14 box: columns 2-13, rows 2-15
    "................",
    "................",
    ".....kkkkkk.....",
    "....kVVVVVVk....",
    "...kVmmVVkkVk...",
    "..kVmVVVVVwwwk..",
    "..kVVVVVVwwkkwk.",
    "..kVVVVVVwwkkwk.",
    "..kVVVVVVVwwwk..",
    "..kvVVVVVVVVVk..",
    "..kvvVVkkkkVvk..",
    "...kvvvvvvvvk...",
    "....kkkkkkkk....",
    "....k22k.k22k...",
    "...k233k.k233k..",
    "...kkkkk.kkkkk..",
]

WALKER_STEP = [
    "................",
    "................",
    "................",
    ".....kkkkkk.....",
    "....kVVVVVVk....",
    "...kVmmVVkkVk...",
    "..kVmVVVVVwwwk..",
    "..kVVVVVVwwkkwk.",
    "..kVVVVVVwwkkwk.",
    "..kVVVVVVVwwwk..",
    "..kvVVVVVVVVVk..",
    "..kvvVVkkkkVvk..",
    "...kvvvvvvvvk...",
    "...kkkkkkkkkk...",
    "...k233kk233k...",
    "...kkkkkkkkkk...",
]

SHIP = [  # the player's ship, nose up; 12x12 box: columns 2-13, rows 4-15
    "................",
    ".......kk.......",
    "......k44k......",
    "......k44k......",
    ".....k4CC4k.....",
    ".....k4Ci4k.....",
    ".....k4CC4k.....",
    "....k344443k....",
    ".k..k344443k..k.",
    "kRk.k344443k.kRk",
    "kRkk33444433kkRk",
    "kRR3334444333RRk",
    "kR333k3443k333Rk",
    "kkkkk.k33k.kkkkk",
    "......kYYk......",
    ".......ff.......",
]

ENEMY_SHIP = [  # nose down; 16x12 box: rows 4-15
    "................",
    "................",
    "................",
    "................",
    "..k..........k..",
    "...k..kkkk..k...",
    "...kkkGGGGkkk...",
    "..kGGGGGGGGGGk..",
    ".kGGLGGGGGGLGGk.",
    "kGGkwkGGGGkwkGGk",
    "kGGkkkGGGGkkkGGk",
    "kgGGGGGGGGGGGGgk",
    ".kggGGkkkkGGggk.",
    "..kkgk.kk.kgkk..",
    "...kgk....kgk...",
    "...kk......kk...",
]

ENEMY_SHIP_FLAP = [
    "................",
    "................",
    "................",
    "................",
    ".k............k.",
    "..k...kkkk...k..",
    "...kkkGGGGkkk...",
    "..kGGGGGGGGGGk..",
    ".kGGLGGGGGGLGGk.",
    "kGGkwkGGGGkwkGGk",
    "kGGkkkGGGGkkkGGk",
    "kgGGGGGGGGGGGGgk",
    ".kggGGkkkkGGggk.",
    "..kkgk.kk.kgkk..",
    "..kgk......kgk..",
    "..kk........kk..",
]

BULLET = [  # 2x6 box: columns 7-8, rows 10-15
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    ".......ZZ.......",
    "......YwwY......",
    "......YwwY......",
    "......YZZY......",
    ".......YY.......",
    ".......dd.......",
]

BOX = [  # a crate; 12x12 box: columns 2-13, rows 4-15
    "................",
    "................",
    "................",
    "................",
    "..kkkkkkkkkkkk..",
    "..kyyyyyyyyytk..",
    "..kyoooooooytk..",
    "..kyooooooytnk..",
    "..kyoooooytonk..",
    "..kynnnnytnnnk..",
    "..kyoooytooonk..",
    "..kyooytoooonk..",
    "..kyoytooooonk..",
    "..kyytoooooonk..",
    "..ktnnnnnnnnnk..",
    "..kkkkkkkkkkkk..",
]

COIN = [  # 8x8 box: columns 4-11, rows 8-15
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "......kkkk......",
    ".....kZZYYk.....",
    "....kZYYYYdk....",
    "....kZYdYYdk....",
    "....kYYdYYdk....",
    "....kYYYYddk....",
    ".....kYdddk.....",
    "......kkkk......",
]

GOAL = [  # a flag on a pole (the goal object is 16x32: it stands on its bottom)
    "...kk...........",
    "..kZYk..........",
    "..kYdkkkk.......",
    "...k4kRRRkkkk...",
    "...k4kpRRRRRRkk.",
    "...k4kppRRRRRRRk",
    "...k4kpRRRRRRRRk",
    "...k4kRRRRRRRRk.",
    "...k4krRRRRRRrk.",
    "...k4krrkkkrrrk.",
    "...k4kkk...kkk..",
    "...k4k..........",
    "...k3k..........",
    "..kk3kk.........",
    ".k33332k........",
    ".kkkkkkk........",
]

GOAL_WAVE = [  # the goal's second frame: the cloth rippled the other way
    "...kk...........",
    "..kZYk..........",
    "..kYdk..........",
    "...k4kkkk.......",
    "...k4kRRRkkkkk..",
    "...k4kpRRRRRRRkk",
    "...k4kppRRRRRRRk",
    "...k4kpRRRRRRRRk",
    "...k4kRRRRRRRRk.",
    "...k4krRRRRRrrk.",
    "...k4krrkkkkkk..",
    "...k4kkk........",
    "...k3k..........",
    "..kk3kk.........",
    ".k33332k........",
    ".kkkkkkk........",
]

# Tiled tile animations in sprites.tsx: (sprite, [(frame sprite, ms), ...]).
# The renderer plays them by the game's clock wherever the sprite is drawn.
ANIMATIONS = [("goal", [("goal", 300), ("goal-wave", 300)])]

MOVING_PLATFORM = [  # a 16x8 piece of a lift or raft: rows 8-15
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "kkkkkkkkkkkkkkkk",
    "k44444444444444k",
    "k3w3333333333w3k",
    "k22222222222222k",
    "kYkkYYkkYYkkYYkk",
    "kkYYkkYYkkYYkkYk",
    "k11111111111111k",
    "kkkkkkkkkkkkkkkk",
]

BALL = [  # 8x8 box: columns 4-11, rows 8-15
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "......kkkk......",
    ".....kpwRRk.....",
    "....kpwRRRRk....",
    "....kRRRRRRk....",
    "....kRRRRRrk....",
    "....krRRRrrk....",
    ".....krrrrk.....",
    "......kkkk......",
]

SPIKES = [  # 8x16 box: columns 4-11
    ".......kkkkk....",
    ".....kk4342k....",
    "....k443342k....",
    ".....kk2242k....",
    ".......kk42k....",
    ".....kk4342k....",
    "....k443342k....",
    ".....kk2242k....",
    ".......kk42k....",
    ".....kk4342k....",
    "....k443342k....",
    ".....kk2242k....",
    ".......kk42k....",
    "....kkkkkkkk....",
    "....k333322k....",
    "....kkkkkkkk....",
]

EXPLOSION = [  # a hit: a burst roughly centred on a 16x12 enemy
    "................",
    "................",
    "................",
    "......k...k.....",
    "..k..kfk.kfk..k.",
    "..kfkkYfkfYfkkf.",
    "...kfYZYfYZYfk..",
    "..kfYZwwZZwZYfk.",
    "...kfZwwwwwZfk..",
    "..kfYZwwwwZYfk..",
    ".kffYZZwwZZYffk.",
    "..kkfYZZZZYfkk..",
    "...kfYfYYfYfk...",
    "..kfk.kffk.kfk..",
    "..kk...kk...kk..",
    "................",
]

SPRITES = [
    ("player", PLAYER),
    ("player-run", PLAYER_RUN),
    ("player-jump", PLAYER_JUMP),
    ("walker", WALKER),
    ("walker-step", WALKER_STEP),
    ("ship", SHIP),
    ("enemy-ship", ENEMY_SHIP),
    ("enemy-ship-flap", ENEMY_SHIP_FLAP),
    ("bullet", BULLET),
    ("box", BOX),
    ("coin", COIN),
    ("goal", GOAL),
    ("moving-platform", MOVING_PLATFORM),
    ("ball", BALL),
    ("spikes", SPIKES),
    ("explosion", EXPLOSION),
    ("goal-wave", GOAL_WAVE),  # last, so no earlier sprite's id moves
]


# ---------------------------------------------------------------- pictures
def check(name, art):
    assert len(art) == TILE, f"{name}: {len(art)} rows, not {TILE}"
    for y, row in enumerate(art):
        assert len(row) == TILE, f"{name} row {y}: {len(row)} pixels, not {TILE}"
        bad = set(row) - set(PALETTE)
        assert not bad, f"{name} row {y}: colours not in the palette: {sorted(bad)}"


def rgba(c):
    return PALETTE[c] if len(PALETTE[c]) == 4 else PALETTE[c] + (255,)


def sheet(pictures, columns):
    """The pictures (each TILE rows of TILE chars) laid out COLUMNS a row, as
    rows of RGBA tuples; cells past the last picture are transparent."""
    rows_of_cells = -(-len(pictures) // columns)
    out = [[PALETTE["."]] * (columns * TILE) for _ in range(rows_of_cells * TILE)]
    for i, art in enumerate(pictures):
        ox, oy = (i % columns) * TILE, (i // columns) * TILE
        for y, row in enumerate(art):
            for x, c in enumerate(row):
                out[oy + y][ox + x] = rgba(c)
    return out


def png(pixels, scale=1):
    """A PNG file (8-bit RGBA, no interlace, filter 0 on every row) of PIXELS,
    rows of (r, g, b, a); SCALE > 1 repeats each pixel SCALE x SCALE times."""
    rows = [[p for p in row for _ in range(scale)] for row in pixels for _ in range(scale)]
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(v for p in row for v in p) for row in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # RGBA, 8 bits
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


# ---------------------------------------------------------------- backdrop.png
# The platformer's far background, an image layer repeated along x that
# scrolls at a third of the camera's speed (parallaxx 0.33): a sky that
# darkens upward and two ranges of hills whose outlines repeat every
# BACKDROP_WIDTH px, so the picture tiles without a seam.
BACKDROP_WIDTH, BACKDROP_HEIGHT = 192, 240


def backdrop():
    def mix(a, b, t):
        return tuple(round(x + (y - x) * t) for x, y in zip(a, b))

    def ridge(x, base, amp, phase):
        w = 2 * math.pi * x / BACKDROP_WIDTH
        return base - amp * (0.6 * math.sin(w + phase) + 0.4 * math.sin(3 * w + 2 * phase))

    rows = []
    for y in range(BACKDROP_HEIGHT):
        row = []
        for x in range(BACKDROP_WIDTH):
            if y > ridge(x, 150, 22, 0.0):
                c = (52, 70, 96)       # near hills
            elif y > ridge(x, 120, 30, 1.7):
                c = (74, 96, 128)      # far hills
            else:
                c = mix((34, 46, 84), (118, 150, 186), y / 150)  # sky
            row.append(c + (255,))
        rows.append(row)
    return rows


def tsx_head(name, count, columns):
    """The first lines of a tileset of COUNT TILE×TILE tiles, COLUMNS a row,
    over NAME.png (sheet() lays it out so)."""
    rows = -(-count // columns)
    return [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<tileset version="1.10" tiledversion="1.10.2" name="{name}" tilewidth="{TILE}" '
        f'tileheight="{TILE}" tilecount="{count}" columns="{columns}">',
        f' <image source="{name}.png" width="{columns * TILE}" height="{rows * TILE}"/>',
    ]


def sprites_tsx():
    lines = tsx_head("sprites", len(SPRITES), SHEET_COLUMNS)
    ids = {kind: i for i, (kind, _) in enumerate(SPRITES)}
    plays = dict(ANIMATIONS)
    for i, (kind, _) in enumerate(SPRITES):
        if kind not in plays:
            lines.append(f' <tile id="{i}" type="{kind}"/>')
            continue
        lines.append(f' <tile id="{i}" type="{kind}">')
        lines.append('  <animation>')
        lines += [f'   <frame tileid="{ids[f]}" duration="{ms}"/>' for f, ms in plays[kind]]
        lines.append('  </animation>')
        lines.append(' </tile>')
    lines.append("</tileset>")
    return "\n".join(lines) + "\n"


def write(path, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(path, mode, **({} if mode == "wb" else {"encoding": "utf-8", "newline": "\n"})) as f:
        f.write(data)


def main(argv):
    for i, art in enumerate(TILES):
        check(f"tile {i}", art)
    for i, art in enumerate(LEVEL_TILES):
        check(f"level tile {i}", art)
    for kind, art in SPRITES:
        check(kind, art)
    for i in (0, 1):  # ground and wall tile under and beside everything: opaque
        assert "." not in "".join(TILES[i]), f"tile {i} must be opaque"

    tiles = sheet(TILES, len(TILES))
    sprites = sheet([art for _, art in SPRITES], SHEET_COLUMNS)
    level_tiles = sheet(LEVEL_TILES, len(LEVEL_TILES))
    write(os.path.join(HERE, "tiles.png"), png(tiles))
    write(os.path.join(HERE, "level-tiles.png"), png(level_tiles))
    write(os.path.join(HERE, "sprites.png"), png(sprites))
    write(os.path.join(HERE, "sprites.tsx"), sprites_tsx())
    write(os.path.join(HERE, "backdrop.png"), png(backdrop()))

    if len(argv) == 3 and argv[1] == "--preview":
        os.makedirs(argv[2], exist_ok=True)
        write(os.path.join(argv[2], "tiles-x8.png"), png(tiles, 8))
        write(os.path.join(argv[2], "level-tiles-x8.png"), png(level_tiles, 8))
        write(os.path.join(argv[2], "sprites-x8.png"), png(sprites, 8))
    elif len(argv) != 1:
        sys.exit(f"usage: {argv[0]} [--preview DIR]")


if __name__ == "__main__":
    main(sys.argv)
