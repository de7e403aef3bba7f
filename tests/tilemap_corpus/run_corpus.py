#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The tilemap corpus test: for every map in maps/MANIFEST, the dump
downstroke-dump-map prints from ds::load_tilemap must equal the one
decode_tiled.py prints from the file. Stops at the first mismatch with a
unified diff.

    run_corpus.py --dump-map PATH [--corpus DIR] [--disable FEATURE,...]

What is compared is switched by features, so that a part the loader cannot
read (on a branch, or after a regression being worked on) can be left out of
the comparison by name, not by accident:

- dump parts (decode_tiled.ALL_PARTS): shapes (object kinds and points),
  templates (template instances resolved), nested-props (class and list
  members), tree (the layer tree), tileset-extra (tile offsets, animations,
  classes, layer offsets);
- what a map needs to load at all (MANIFEST's needs=): json (.tmj maps,
  .tsj tilesets), templates (.tx), sparse (gids beyond a tileset, sparse
  image collections: their warnings, and the refusal under --strict, are
  checked against the cells the decoder finds), text-encodings (a map
  declaring ISO-8859-1), project (a map loaded with its Tiled project file,
  whose class defaults fill the members the map leaves out).

Every feature is compared by default; --disable (or DS_CORPUS_DISABLE,
comma-separated) leaves some out, and maps needing a disabled feature are
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

LOAD_FEATURES = ("json", "sparse", "text-encodings", "project")  # and templates, a dump part too
ALL_FEATURES = tuple(p for p in decode_tiled.ALL_PARTS if p != "base") + LOAD_FEATURES


def read_manifest(corpus):
    entries = []
    with open(os.path.join(corpus, "MANIFEST"), encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            fields = line.split()
            needs, project = set(), None
            for extra in fields[1:]:
                if extra.startswith("needs="):
                    needs |= set(extra[len("needs="):].split(","))
                elif extra.startswith("project="):
                    project = os.path.join(corpus, extra[len("project="):])
            entries.append((fields[0], needs, project))
    return entries


def features_from(args):
    disabled = set()
    for text in (args.disable, os.environ.get("DS_CORPUS_DISABLE", "")):
        disabled |= {f for f in text.split(",") if f}
    unknown = disabled - set(ALL_FEATURES)
    if unknown:
        raise SystemExit("run_corpus: unknown feature(s) %s (known: %s)" % (
            ", ".join(sorted(unknown)), ", ".join(ALL_FEATURES)))
    return set(ALL_FEATURES) - disabled


def loader_dump(dump_map, path, parts_arg, strict=False, project=None):
    args = [dump_map, parts_arg] + (["--strict"] if strict else [])
    args += (["--project=" + project] if project else []) + [path]
    r = subprocess.run(args, capture_output=True, timeout=60)
    # Bytes that are not UTF-8 show in the diff instead of stopping it.
    return r.returncode, r.stdout.decode("utf-8", "backslashreplace"), r.stderr.decode("utf-8", "backslashreplace")


def decoder_dump(path, parts, project):
    try:
        m = decode_tiled.read_map(path, parts, project)
        return "\n".join(decode_tiled.dump(m, parts)) + "\n", "", m
    except Exception as e:  # the decoder refusing a corpus map is a broken corpus
        return None, "%s: %s" % (type(e).__name__, e), None


def gid_text(raw):
    text = str(raw & decode_tiled.GID_MASK)
    if raw & decode_tiled.FLIP_BITS:
        text += " (raw 0x%08X)" % raw
    return text


def beyond_text(layer, raw, col, row):
    return "gid %s at cell (%d, %d) of layer '%s' is beyond every tileset" % (gid_text(raw), col, row, layer)


def check_warnings(rel, path, m, stderr, dump_map, parts_arg):
    """Gids beyond every tileset (semantics §7, issue 22 item 4): one warning
    per layer naming the map, the layer, its first such cell and how many
    there are; with --strict the map is refused naming the first of them.
    None when all is as predicted, else what went wrong."""
    expected = []
    for layer, raw, col, row, count in decode_tiled.unknown_gids(m):
        expected.append((beyond_text(layer, raw, col, row), count))
    warnings = [l[len("warning: "):] for l in stderr.splitlines() if l.startswith("warning: ")]
    if len(warnings) != len(expected):
        return "%d warnings where the decoder finds %d layers with gids beyond every tileset:\n%s" % (
            len(warnings), len(expected), "\n".join(warnings))
    for (text, count), got in zip(expected, warnings):
        others = " (%d cells in all)" % count if count > 1 else ""
        if not got.startswith(path) or text + others + ";" not in got:
            return "warning %r does not name %s and %r%s" % (got, path, text, others)
    if expected:
        rc, _out, err = loader_dump(dump_map, path, parts_arg, strict=True)
        if rc != 1 or expected[0][0] not in err or not err.startswith(path):
            return "--strict: exit %d, %r; expected a refusal naming %s and %r" % (rc, err, path, expected[0][0])
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dump-map", required=True)
    ap.add_argument("--corpus", default=os.path.join(HERE, "maps"))
    ap.add_argument("--disable", default="")
    args = ap.parse_args()
    enabled = features_from(args)
    parts = {"base"} | (enabled & set(decode_tiled.ALL_PARTS))
    parts_arg = "--parts=" + ",".join(sorted(parts))
    print("corpus: comparing parts %s" % ", ".join(sorted(parts)))

    checked, warned, skipped = 0, 0, {}
    for rel, needs, project in read_manifest(args.corpus):
        missing = needs - enabled
        if missing:
            key = ",".join(sorted(missing))
            skipped[key] = skipped.get(key, 0) + 1
            continue
        path = os.path.join(args.corpus, rel)
        expected, problem, decoded = decoder_dump(path, parts, project)
        if expected is None:
            print("FAIL %s: the decoder cannot read it: %s" % (rel, problem))
            return 1
        rc, actual, err = loader_dump(args.dump_map, path, parts_arg, project=project)
        if project:
            rel += " with " + os.path.relpath(project, args.corpus)
        if rc != 0:
            print("FAIL %s: the loader refused it:\n%s" % (rel, err))
            return 1
        if actual != expected:
            diff = difflib.unified_diff(expected.splitlines(True), actual.splitlines(True),
                                        "decode_tiled.py " + rel, "ds::load_tilemap " + rel)
            print("FAIL %s: the loader's model differs from the decoder's reading:" % rel)
            sys.stdout.writelines(diff)
            return 1
        if "sparse" in enabled:
            problem = check_warnings(rel, path, decoded, err, args.dump_map, parts_arg)
            if problem:
                print("FAIL %s: %s" % (rel, problem))
                return 1
            warned += bool(decode_tiled.unknown_gids(decoded))
        checked += 1
    print("corpus: %d maps agree" % checked)
    if "sparse" in enabled:
        print("corpus: %d of them with gids beyond a tileset, warned about and refused "
              "under --strict as predicted" % warned)
    for f in sorted(skipped):
        print("corpus: %d maps skipped, needing %s (disabled)" % (skipped[f], f))
    if checked == 0:
        print("FAIL: no map was compared")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
