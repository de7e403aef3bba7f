#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates tests/data/maps/json: the JSON twins (.tmj, .tsj) of the TMX
test maps, used by tests/core/tmj_test.cpp, which loads each pair and
asserts the same model.

The outputs are checked in; the build never runs this. Run it from anywhere:
    python3 tests/data/make_json_maps.py
Each twin is written as Tiled's JSON map format writes the same map: tile
data as an array of gids where the TMX has XML or CSV, as the same base64
string (with the same compression) where it has base64; properties with
typed values; tilesets named by .tsj instead of .tsx. The TMX is read with
ElementTree, not with the loader, so the twin is an independent statement.
"""
import json
import os
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
MAPS = os.path.join(HERE, "maps")
OUT = os.path.join(MAPS, "json")

INT_ATTRS = {"id", "width", "height", "tilewidth", "tileheight", "tilecount", "columns", "spacing",
             "margin", "firstgid", "nextlayerid", "nextobjectid", "gid", "tileid", "duration"}
NUM_ATTRS = {"x", "y", "rotation", "opacity", "offsetx", "offsety", "parallaxx", "parallaxy"}


def number(text):
    v = float(text)
    return int(v) if v == int(v) and "." not in text else v


def prop_value(p):
    kind = p.get("type", "string")
    text = p.get("value", p.text or "")
    if kind in ("int", "object"):
        return int(text)
    if kind == "float":
        return number(text)
    if kind == "bool":
        return text == "true"
    return text


def properties(e):
    out = []
    ps = e.find("properties")
    for p in ps.findall("property") if ps is not None else []:
        out.append({"name": p.get("name"), "type": p.get("type", "string"), "value": prop_value(p)})
    return out


def with_props(d, e):
    props = properties(e)
    if props:
        d["properties"] = props
    return d


def gids(data):
    enc = data.get("encoding")
    if enc is None:
        return [int(t.get("gid", "0")) for t in data.findall("tile")]
    if enc == "csv":
        text = (data.text or "").strip()
        return [int(v) for v in text.replace("\n", "").split(",") if v.strip()] if text else []
    return (data.text or "").strip()  # base64: the same string


def text_of(t):
    d = {"text": t.text or ""}
    for k in ("fontfamily", "color", "halign", "valign"):
        if t.get(k) is not None:
            d[k] = t.get(k)
    if t.get("pixelsize") is not None:
        d["pixelsize"] = int(t.get("pixelsize"))
    for k in ("wrap", "bold", "italic", "underline", "strikeout", "kerning"):
        if t.get(k) is not None:
            d[k] = t.get(k) == "1"
    return d


def obj(o):
    """Only the fields the TMX writes, as Tiled's JSON does for a template
    instance (the rest comes from its template)."""
    d = {"id": int(o.get("id", "0"))}
    if o.get("template"):
        d["template"] = o.get("template").replace(".tx", ".tj")
    for k in ("name", "type", "class"):
        if o.get(k) is not None:
            d[k] = o.get(k)
    for k in ("x", "y", "width", "height", "rotation"):
        if o.get(k) is not None:
            d[k] = number(o.get(k))
    if o.get("gid"):
        d["gid"] = int(o.get("gid"))
    if o.get("visible") is not None:
        d["visible"] = o.get("visible") == "1"
    if o.find("point") is not None:
        d["point"] = True
    if o.find("ellipse") is not None:
        d["ellipse"] = True
    for shape in ("polygon", "polyline"):
        s = o.find(shape)
        if s is not None:
            d[shape] = [{"x": number(a), "y": number(b)} for a, b in
                        (pt.split(",") for pt in s.get("points").split())]
    if o.find("text") is not None:
        d["text"] = text_of(o.find("text"))
    return with_props(d, o)


def convert_template(src, dst):
    root = ET.parse(os.path.join(MAPS, src)).getroot()
    d = {"type": "template", "object": obj(root.find("object"))}
    d["object"].pop("template", None)  # templates do not nest
    ts = root.find("tileset")
    if ts is not None:
        d["tileset"] = {"firstgid": int(ts.get("firstgid")), "source": ts.get("source").replace(".tsx", ".tsj")}
    write(dst, d)


def layer_common(e, kind):
    d = {"id": int(e.get("id", "0")), "name": e.get("name", ""), "type": kind,
         "opacity": number(e.get("opacity", "1")), "visible": e.get("visible", "1") == "1",
         "x": 0, "y": 0}
    return with_props(d, e)


def layer(e, infinite):
    tag = e.tag
    if tag == "layer":
        d = layer_common(e, "tilelayer")
        data = e.find("data")
        if data.get("encoding") == "base64":
            d["encoding"] = "base64"
            if data.get("compression"):
                d["compression"] = data.get("compression")
        if infinite:
            d["chunks"] = [{"data": gids_of(c, data), "x": int(c.get("x")), "y": int(c.get("y")),
                            "width": int(c.get("width")), "height": int(c.get("height"))}
                           for c in data.findall("chunk")]
        else:
            d["data"] = gids(data)
        d["width"] = int(e.get("width"))
        d["height"] = int(e.get("height"))
        return d
    if tag == "objectgroup":
        d = layer_common(e, "objectgroup")
        d["draworder"] = "topdown"
        d["objects"] = [obj(o) for o in e.findall("object")]
        if e.get("color"):
            d["color"] = e.get("color")
        return d
    if tag == "imagelayer":
        d = layer_common(e, "imagelayer")
        img = e.find("image")
        d.update({"image": img.get("source"), "imagewidth": int(img.get("width")),
                  "imageheight": int(img.get("height"))})
        return d
    if tag == "group":
        d = layer_common(e, "group")
        d["layers"] = layers(e, infinite)
        return d
    return None


def gids_of(chunk, data):
    chunk.set("encoding", data.get("encoding")) if data.get("encoding") else None
    return gids(chunk)


def layers(parent, infinite):
    return [d for d in (layer(c, infinite) for c in parent) if d is not None]


def tile(t):
    d = {"id": int(t.get("id"))}
    kind = t.get("type") or t.get("class")
    if kind:
        d["type"] = kind
    img = t.find("image")
    if img is not None:
        d.update({"image": img.get("source"), "imagewidth": int(img.get("width")),
                  "imageheight": int(img.get("height"))})
    group = t.find("objectgroup")
    if group is not None:
        d["objectgroup"] = {"draworder": "index", "id": int(group.get("id", "0")), "name": "",
                            "objects": [obj(o) for o in group.findall("object")],
                            "opacity": 1, "type": "objectgroup", "visible": True, "x": 0, "y": 0}
    anim = t.find("animation")
    if anim is not None:
        d["animation"] = [{"tileid": int(f.get("tileid")), "duration": int(f.get("duration"))}
                          for f in anim.findall("frame")]
    return with_props(d, t)


def tileset_body(e):
    d = {"name": e.get("name", "")}
    for k in ("tilewidth", "tileheight", "tilecount", "columns", "spacing", "margin"):
        if e.get(k) is not None:
            d[k] = int(e.get(k))
    img = e.find("image")
    if img is not None:
        d.update({"image": img.get("source"), "imagewidth": int(img.get("width")),
                  "imageheight": int(img.get("height"))})
    tiles = [tile(t) for t in e.findall("tile")]
    if tiles:
        d["tiles"] = tiles
    return with_props(d, e)


def tileset_ref(e):
    if e.get("source"):
        return {"firstgid": int(e.get("firstgid")), "source": e.get("source").replace(".tsx", ".tsj")}
    d = {"firstgid": int(e.get("firstgid"))}
    d.update(tileset_body(e))
    return d


def convert_map(src, dst):
    root = ET.parse(os.path.join(MAPS, src)).getroot()
    infinite = root.get("infinite") == "1"
    d = {"type": "map", "version": "1.10", "tiledversion": "1.10.2", "compressionlevel": -1,
         "orientation": root.get("orientation"), "renderorder": root.get("renderorder", "right-down"),
         "width": int(root.get("width")), "height": int(root.get("height")),
         "tilewidth": int(root.get("tilewidth")), "tileheight": int(root.get("tileheight")),
         "infinite": infinite, "nextlayerid": int(root.get("nextlayerid", "1")),
         "nextobjectid": int(root.get("nextobjectid", "1")),
         "tilesets": [tileset_ref(t) for t in root.findall("tileset")],
         "layers": layers(root, infinite)}
    write(dst, with_props(d, root))


def convert_tileset(src, dst):
    root = ET.parse(os.path.join(MAPS, src)).getroot()
    d = {"type": "tileset", "version": "1.10", "tiledversion": "1.10.2"}
    d.update(tileset_body(root))
    write(dst, d)


def write(rel, data):
    path = os.path.join(OUT, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        json.dump(data, f, indent=1, ensure_ascii=False)
        f.write("\n")


def main():
    for enc in ("xml", "csv", "base64", "zlib", "gzip", "zstd", "zstd_stream"):
        convert_map(f"level_{enc}.tmx", f"level_{enc}.tmj")
    for name in ("layers", "tilesets", "infinite"):
        convert_map(f"{name}.tmx", f"{name}.tmj")
    convert_tileset("tilesets/terrain.tsx", "tilesets/terrain.tsj")
    # The TMX features (tests/data/make_feature_maps.py): shapes and text,
    # templates in maps and in a tileset's tile.
    for name in ("objects", "templates", "template_rules"):
        convert_map(f"features/{name}.tmx", f"features/{name}.tmj")
    for name in ("spawn", "crate", "self", "placed"):
        convert_template(f"features/templates/{name}.tx", f"features/templates/{name}.tj")


if __name__ == "__main__":
    main()
