#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the plist target's seed recipes (seeds/plist/) in the byte language
fuzz_plist.cpp reads: typical entities (a falling box, a player on the ground,
a pushed pair, a group), so fuzzing starts from plists that reach every step;
and (regressions/plist/) the circular lists the native walks once hung on,
next to the one the fuzzer found. Run it after changing that
language; the files are committed."""
import os
import struct

# Key indices: the rows of src/body_fields.def, then #:tween.
KEYS = {k: i for i, k in enumerate(
    "x y width height vx vy ay group-local-x group-local-y gravity? on-ground? solid? "
    "immovable? group-origin? skip-pipelines id group-id tween".split())}


def key(name):
    return bytes([0, KEYS[name]])  # key(): choice 0 is a physics key


def small(n):
    # value(): choice 0 (a number); number(): choice 6, an int16 in eighths
    return bytes([0, 6]) + struct.pack(">h", int(n * 8))


def flag(on):
    return bytes([3, 1 if on else 0])


def entity(**fields):
    out = bytes([len(fields)])
    for name, v in fields.items():
        name = name.replace("_", "-").replace("Q", "?")
        out += key(name) + (flag(v) if isinstance(v, bool) else small(v))
    return out + bytes([1, 0])  # not a dangling key; a proper tail


def scene(*entities, tail=bytes([0])):
    # entity_list(): count-1, the entities, how the list ends (close_list());
    # then the step arguments (map, mode, dt, substeps)
    return bytes([len(entities) - 1]) + b"".join(entities) + tail + bytes([1, 1, 1, 1, 0])


def circular_skips():
    # key 14 (#:skip-pipelines); value() choice 6, a list of two skip symbols,
    # its last pair tied back to the first (close_list() choice 7, pair 0)
    return bytes([1]) + key("skip-pipelines") + bytes([6, 2, 1, 0, 1, 1, 7, 0]) + bytes([1, 0])


def circular_id():
    # key 15 (#:id), a list of two symbols tied back to its first pair, as
    # in circular_skips(): a second entity with an equal one made equal? loop
    return bytes([1]) + key("id") + bytes([6, 2, 1, 0, 1, 1, 7, 0]) + bytes([1, 0])


SEEDS = {
    "falling-box": scene(entity(x=10, y=0, width=8, height=8, vy=1, gravityQ=True)),
    "player-on-ground": scene(entity(x=16, y=40, width=12, height=16, vx=2, gravityQ=True, on_groundQ=True)),
    "pushed-pair": scene(entity(x=0, y=20, width=16, height=16, vx=3, solidQ=True),
                         entity(x=14, y=20, width=16, height=16, solidQ=True, immovableQ=False)),
    "group": scene(entity(x=30, y=10, width=4, height=4, group_id=1, group_originQ=True),
                   entity(x=0, y=0, width=4, height=4, group_id=1, group_local_x=5, group_local_y=-2)),
}

CIRCULAR = {
    "circular-skip-pipelines": scene(circular_skips()),
    "circular-entity-list": scene(entity(x=1), entity(y=2), tail=bytes([7, 0])),
    "timeout-circular-id": scene(circular_id(), circular_id()),
}

root = os.path.dirname(os.path.abspath(__file__))
for folder, files in (("seeds", SEEDS), ("regressions", CIRCULAR)):
    here = os.path.join(root, folder, "plist")
    os.makedirs(here, exist_ok=True)
    for name, data in files.items():
        with open(os.path.join(here, name), "wb") as f:
            f.write(data)
