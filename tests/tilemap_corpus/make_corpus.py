#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Rebuilds tests/tilemap_corpus/maps/ with the real Tiled editor.

    QT_QPA_PLATFORM=offscreen tests/tilemap_corpus/make_corpus.py

Needs Tiled (Debian 12: `apt-get install tiled`, 1.8.2) only to *make* the
corpus; the test (run_corpus.py) reads the checked-in outputs. For each map
the project ships (demo/maps, bench/maps, tests/data/maps and its render/
maps; not bad/ or hostile/) and each hand-made feature map in sources/:

- its tilesets, re-saved by Tiled as .tsx and exported as .tsj;
- the map with its layer data rewritten here into each encoding (XML
  tiles, CSV, base64, base64+zlib/gzip/zstd), then loaded and re-saved by
  Tiled, so that every corpus file is Tiled's own writing: NAME.ENC.tmx;
- the maps of tests/data/maps also as shipped (data-shipped/), with their
  JSON twins (tests/data/maps/json);
- each of those exported to JSON (NAME.ENC.tmj; XML tiles and CSV are both
  an array there, so the CSV one stands for both), the CSV one with its
  tilesets embedded (NAME.embedded.tmj), and the CSV one naming the .tsj
  tilesets, as TMX and as JSON (NAME.tsj.tmx, NAME.tsj.tmj).

Pictures a map names but the repository does not hold are written as
placeholder PNGs of the size the file declares, so that Tiled keeps the
tilesets as they are (a tileset whose picture is missing loses its tiles).
MANIFEST lists every map with what the loader must read to load it
(needs=json for JSON maps and tilesets, needs=templates, ...), for
run_corpus.py.
"""
import base64
import gzip
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(HERE, "maps")
ENCODINGS = ("xml", "csv", "base64", "zlib", "gzip", "zstd")

# group → (source folder, maps, extra needs of every map in the group)
GROUPS = {
    "demo": ("demo/maps", ["level1", "platformer", "sandbox", "shmup", "topdown", "tweens"]),
    "data": ("tests/data/maps", ["infinite", "layers", "level_csv", "tilesets"]),
    # Copied as shipped (Tiled 1.10's writing, and a zstd stream without a
    # content size), beside the re-saved tilesets: the level_* maps are one
    # map in each encoding, which the re-saved level_csv covers again.
    "data-shipped": ("tests/data/maps", None),
    "render": ("tests/data/maps/render", ["render", "no-image"]),
    "features": ("tests/tilemap_corpus/sources", None),  # every .tmx there
}
# bench's map names the demo's tilesets (../../demo/maps/): it joins the
# demo group, its tileset paths made local.
BENCH_MAP = "bench/maps/platformer-60x15.tmx"

# What a map needs the loader to read beyond what it read before issue 22
# (run_corpus.py's features), by group/name. data/tilesets: its image
# collection has tilecount="0" and a gid 100 in it, which Tiled re-saves as
# tilecount="2" (ids 0 and 5) and gid 88, beyond the collection's tiles.
MAP_NEEDS = {
    "data/tilesets": {"sparse"},
    "features/templates": {"templates"},
    "features/sparse": {"sparse"},
}


def tiled(*args):
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    r = subprocess.run(["tiled", *args], env=env, capture_output=True, text=True)
    noise = [l for l in (r.stdout + r.stderr).splitlines() if "XDG_RUNTIME_DIR" not in l and l.strip()]
    if r.returncode != 0:
        raise SystemExit("tiled %s failed:\n%s" % (" ".join(args), "\n".join(noise)))
    for l in noise:
        print("  tiled: " + l, file=sys.stderr)


# --- placeholder pictures -----------------------------------------------------

def png(width, height):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    rows = b"".join(b"\x00" + b"\x80\x80\x80" * width for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def add_placeholders(xml_path):
    root = ET.parse(xml_path).getroot()
    folder = os.path.dirname(xml_path)
    for img in root.iter("image"):
        src = img.get("source")
        if not src:
            continue
        target = os.path.normpath(os.path.join(folder, src))
        if os.path.exists(target):
            continue
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "wb") as f:
            f.write(png(int(img.get("width", "16")), int(img.get("height", "16"))))


# --- layer data in each encoding ----------------------------------------------

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import decode_tiled  # noqa: E402  (its decoding of the source maps' data)


def encode(gids, enc):
    raw = b"".join(struct.pack("<I", g) for g in gids)
    if enc == "base64":
        return base64.b64encode(raw).decode()
    if enc == "zlib":
        return base64.b64encode(zlib.compress(raw)).decode()
    if enc == "gzip":
        return base64.b64encode(gzip.compress(raw, mtime=0)).decode()
    if enc == "zstd":
        import zstandard
        return base64.b64encode(zstandard.ZstdCompressor().compress(raw)).decode()
    raise ValueError(enc)


def fill(el, gids, width, enc):
    for child in list(el):
        if child.tag == "tile":
            el.remove(child)
    if enc == "xml":
        el.text = "\n"
        for g in gids:
            t = ET.SubElement(el, "tile")
            if g:
                t.set("gid", str(g))
        return
    if enc == "csv":
        rows = [",".join(str(g) for g in gids[i:i + width]) for i in range(0, len(gids), width)]
        el.text = "\n" + ",\n".join(rows) + "\n"
    else:
        el.text = "\n" + encode(gids, enc) + "\n"


def reencode(src, dst, enc, map_width, map_height):
    tree = ET.parse(src)
    infinite = decode_tiled.truthy(tree.getroot().get("infinite", "0"))
    for data in tree.getroot().iter("data"):
        old_enc, old_comp = data.get("encoding"), data.get("compression")
        for k in ("encoding", "compression"):
            data.attrib.pop(k, None)
        if enc != "xml":
            data.set("encoding", "csv" if enc == "csv" else "base64")
        if enc in ("zlib", "gzip", "zstd"):
            data.set("compression", enc)
        chunks = data.findall("chunk")
        if infinite:  # an infinite layer holds chunks only, maybe none
            for c in chunks:
                w, h = int(c.get("width")), int(c.get("height"))
                gids = decode_tiled.decode_xml_data(c, old_enc, old_comp, w * h, src)
                fill(c, gids, w, enc)
        else:
            gids = decode_tiled.decode_xml_data(data, old_enc, old_comp, map_width * map_height, src)
            fill(data, gids, map_width, enc)
    tree.write(dst, encoding="UTF-8", xml_declaration=True)


# --- one group ------------------------------------------------------------------

def copy_support(src_dir, out_dir):
    """The tilesets, templates and pictures beside the source maps."""
    for base, _dirs, files in os.walk(src_dir):
        rel = os.path.relpath(base, src_dir)
        if rel.split(os.sep)[0] in ("bad", "hostile", "render", "json") and src_dir.endswith("tests/data/maps"):
            continue
        for f in files:
            if f.endswith((".tsx", ".tx", ".png", ".tiled-project")):
                os.makedirs(os.path.join(out_dir, rel), exist_ok=True)
                shutil.copy(os.path.join(base, f), os.path.join(out_dir, rel, f))


def resave_tilesets(out_dir):
    tilesets = []
    for base, _dirs, files in os.walk(out_dir):
        tilesets += [os.path.join(base, f) for f in files if f.endswith(".tsx")]
    for ts in tilesets:
        add_placeholders(ts)
    with tempfile.TemporaryDirectory() as tmp:
        for ts in tilesets:
            # Tiled writes image paths relative to the file it writes: a
            # temporary copy in the same folder, then moved over.
            tmp_ts = ts[:-4] + ".resaved.tsx"
            tiled("--export-tileset", "tsx", ts, tmp_ts)
            os.replace(tmp_ts, ts)
            tiled("--export-tileset", "json", ts, ts[:-4] + ".tsj")
    return tilesets


def map_size(path):
    root = ET.parse(path).getroot()
    return int(root.get("width", "0")), int(root.get("height", "0"))


def has_external_tilesets(path):
    return any(t.get("source") for t in ET.parse(path).getroot().findall("tileset"))


def make_map(src_map, out_dir, name, needs, manifest):
    staged = os.path.join(out_dir, name + ".source.tmx")
    shutil.copy(src_map, staged)
    add_placeholders(staged)
    w, h = map_size(staged)
    for enc in ENCODINGS:
        tmp = os.path.join(out_dir, "%s.in-%s.tmx" % (name, enc))
        reencode(staged, tmp, enc, w, h)
        out = os.path.join(out_dir, "%s.%s.tmx" % (name, enc))
        tiled("--export-map", "tmx", tmp, out)
        os.remove(tmp)
        manifest.append((out, needs))
        if enc != "xml":
            tmj = out[:-4] + ".tmj"
            tiled("--export-map", "json", out, tmj)
            manifest.append((tmj, needs | {"json"}))
    csv_map = os.path.join(out_dir, name + ".csv.tmx")
    emb = os.path.join(out_dir, name + ".embedded.tmj")
    tiled("--export-map", "--embed-tilesets", "json", csv_map, emb)
    manifest.append((emb, needs | {"json"}))
    if has_external_tilesets(csv_map):
        tmp = os.path.join(out_dir, name + ".in-tsj.tmx")
        with open(csv_map, encoding="utf-8") as f:
            text = f.read()
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text.replace('.tsx"', '.tsj"'))
        tsj_tmx = os.path.join(out_dir, name + ".tsj.tmx")
        tiled("--export-map", "tmx", tmp, tsj_tmx)
        os.remove(tmp)
        tiled("--export-map", "json", tsj_tmx, tsj_tmx[:-4] + ".tmj")
        manifest.append((tsj_tmx, needs | {"json"}))
        manifest.append((tsj_tmx[:-4] + ".tmj", needs | {"json"}))
    os.remove(staged)


def make_group(group, manifest):
    src_rel, names = GROUPS[group]
    src_dir = os.path.join(ROOT, src_rel)
    out_dir = os.path.join(OUT, group)
    os.makedirs(out_dir)
    copy_support(src_dir, out_dir)
    resave_tilesets(out_dir)
    if names is None:
        names = sorted(f[:-4] for f in os.listdir(src_dir) if f.endswith(".tmx"))
    if group == "data-shipped":
        for f in sorted(os.listdir(src_dir)):
            if f.endswith(".tmx"):
                shutil.copy(os.path.join(src_dir, f), os.path.join(out_dir, f))
                manifest.append((os.path.join(out_dir, f), set(MAP_NEEDS.get("data/" + f[:-4], set()))))
        # The JSON twins of those maps (tests/data/maps/json, written by the
        # JSON part's make_json_maps.py), with their tilesets and templates.
        json_src = os.path.join(src_dir, "json")
        shutil.copytree(json_src, os.path.join(out_dir, "json"))
        for f in sorted(os.listdir(json_src)):
            if f.endswith(".tmj"):
                with open(os.path.join(json_src, f), encoding="utf-8") as j:
                    needs = {"json"} | ({"templates"} if '"template"' in j.read() else set())
                manifest.append((os.path.join(out_dir, "json", f), needs))
        return
    for name in names:
        print("corpus: %s/%s" % (group, name))
        needs = set(MAP_NEEDS.get(group + "/" + name, set()))
        make_map(os.path.join(src_dir, name + ".tmx"), out_dir, name, needs, manifest)
    if group == "demo":
        with open(os.path.join(ROOT, BENCH_MAP), encoding="utf-8") as f:
            text = f.read().replace("../../demo/maps/", "")
        with tempfile.NamedTemporaryFile("w", suffix=".tmx", delete=False, encoding="utf-8") as tmp:
            tmp.write(text)
        print("corpus: demo/platformer-60x15 (bench)")
        make_map(tmp.name, out_dir, "platformer-60x15", set(), manifest)
        os.remove(tmp.name)


# Maps written by hand in a newer Tiled's format than Debian's Tiled 1.8 can
# write (class members, list properties), copied into maps/features/ as
# they are.
HANDMADE = os.path.join(HERE, "sources", "handmade")
# A map NAME with a NAME.tiled-project beside it is listed twice, the second
# time with the project (LoadOptions::project_path), needing "project".
# By name; properties.tmx loads without them (its members are the dump's
# nested-props part).
HANDMADE_NEEDS = {"latin1": {"text-encodings"}}


def copy_handmade(manifest):
    out_dir = os.path.join(OUT, "features")
    for f in sorted(os.listdir(HANDMADE)):
        name, ext = os.path.splitext(f)
        shutil.copy(os.path.join(HANDMADE, f), os.path.join(out_dir, f))
        if ext in (".tmx", ".tmj"):
            needs = set(HANDMADE_NEEDS.get(name, set()))
            if ext == ".tmj":
                needs.add("json")
            manifest.append((os.path.join(out_dir, f), needs))
            project = os.path.join(HANDMADE, name + ".tiled-project")
            if os.path.exists(project):  # once more, its class defaults filled in
                manifest.append((os.path.join(out_dir, f), needs | {"project"},
                                 os.path.join(out_dir, name + ".tiled-project")))


def main():
    if shutil.which("tiled") is None:
        raise SystemExit("make_corpus: needs Tiled (Debian: apt-get install tiled)")
    if os.path.isdir(OUT):
        shutil.rmtree(OUT)
    manifest = []
    for group in GROUPS:
        make_group(group, manifest)
    copy_handmade(manifest)
    with open(os.path.join(OUT, "MANIFEST"), "w", encoding="utf-8") as f:
        f.write("# Written by make_corpus.py: each corpus map and what the loader must read to load it.\n")
        for path, needs, *project in manifest:
            line = os.path.relpath(path, OUT)
            if needs:
                line += " needs=" + ",".join(sorted(needs))
            if project:
                line += " project=" + os.path.relpath(project[0], OUT)
            f.write(line + "\n")
    print("corpus: %d maps" % len(manifest))


if __name__ == "__main__":
    main()
