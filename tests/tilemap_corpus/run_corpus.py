#!/usr/bin/python3
"""The tilemap corpus test: for every map in maps/MANIFEST, the dump
downstroke-dump-map prints from ds::load_tilemap must equal the one
decode_tiled.py prints from the file. Stops at the first mismatch with a
unified diff.

    run_corpus.py --dump-map PATH [--corpus DIR] [--enable FEATURE,...] [--all]

What is compared is switched by features, so that a part the loader cannot
read yet stays out of the comparison by name, not by accident:

- dump parts (decode_tiled.ALL_PARTS): shapes (object kinds and points),
  nested-props (class and list members), tree (the layer tree),
  tileset-extra (tile offsets, animations, classes, layer offsets);
- what a map needs to load at all (MANIFEST's needs=): json (.tmj maps,
  .tsj tilesets), templates (.tx), nested-props (class/list members),
  sparse (gids beyond a tileset, sparse image collections), text-encodings
  (a map declaring ISO-8859-1).

DEFAULT_ENABLED is what the loader reads on this branch; --enable adds
features, --all enables every one, and DS_CORPUS_ENABLE (comma-separated)
adds to it from the environment. Maps needing a disabled feature are
skipped and counted in the summary.
"""
import argparse
import difflib
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import decode_tiled  # noqa: E402

LOAD_FEATURES = ("json", "templates", "sparse", "text-encodings")
ALL_FEATURES = tuple(p for p in decode_tiled.ALL_PARTS if p != "base") + LOAD_FEATURES
# What ds::load_tilemap reads on this branch (issue 22 in progress: the JSON
# reader, templates, shapes, class members, the layer tree and text in
# other encodings are still being written).
DEFAULT_ENABLED = ("sparse",)


def read_manifest(corpus):
    entries = []
    with open(os.path.join(corpus, "MANIFEST"), encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            fields = line.split()
            needs = set()
            for extra in fields[1:]:
                if extra.startswith("needs="):
                    needs |= set(extra[len("needs="):].split(","))
            entries.append((fields[0], needs))
    return entries


def features_from(args):
    enabled = set(DEFAULT_ENABLED)
    if args.all:
        enabled |= set(ALL_FEATURES)
    for text in (args.enable, os.environ.get("DS_CORPUS_ENABLE", "")):
        enabled |= {f for f in text.split(",") if f}
    unknown = enabled - set(ALL_FEATURES)
    if unknown:
        raise SystemExit("run_corpus: unknown feature(s) %s (known: %s)" % (
            ", ".join(sorted(unknown)), ", ".join(ALL_FEATURES)))
    return enabled


def loader_dump(dump_map, path, parts_arg):
    r = subprocess.run([dump_map, parts_arg, path], capture_output=True, timeout=60)
    # Bytes that are not UTF-8 show in the diff instead of stopping it.
    return r.returncode, r.stdout.decode("utf-8", "backslashreplace"), r.stderr.decode("utf-8", "backslashreplace")


def decoder_dump(path, parts):
    try:
        return "\n".join(decode_tiled.dump(decode_tiled.read_map(path, parts), parts)) + "\n", ""
    except Exception as e:  # the decoder refusing a corpus map is a broken corpus
        return None, "%s: %s" % (type(e).__name__, e)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dump-map", required=True)
    ap.add_argument("--corpus", default=os.path.join(HERE, "maps"))
    ap.add_argument("--enable", default="")
    ap.add_argument("--all", action="store_true")
    args = ap.parse_args()
    enabled = features_from(args)
    parts = {"base"} | (enabled & set(decode_tiled.ALL_PARTS))
    parts_arg = "--parts=" + ",".join(sorted(parts))
    print("corpus: comparing parts %s" % ", ".join(sorted(parts)))

    checked, skipped = 0, {}
    for rel, needs in read_manifest(args.corpus):
        missing = needs - enabled
        if missing:
            key = ",".join(sorted(missing))
            skipped[key] = skipped.get(key, 0) + 1
            continue
        path = os.path.join(args.corpus, rel)
        expected, problem = decoder_dump(path, parts)
        if expected is None:
            print("FAIL %s: the decoder cannot read it: %s" % (rel, problem))
            return 1
        rc, actual, err = loader_dump(args.dump_map, path, parts_arg)
        if rc != 0:
            print("FAIL %s: the loader refused it:\n%s" % (rel, err))
            return 1
        if actual != expected:
            diff = difflib.unified_diff(expected.splitlines(True), actual.splitlines(True),
                                        "decode_tiled.py " + rel, "ds::load_tilemap " + rel)
            print("FAIL %s: the loader's model differs from the decoder's reading:" % rel)
            sys.stdout.writelines(diff)
            return 1
        checked += 1
    print("corpus: %d maps agree" % checked)
    for f in sorted(skipped):
        print("corpus: %d maps skipped, needing %s (--enable=%s)" % (skipped[f], f, f))
    if checked == 0:
        print("FAIL: no map was compared")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
