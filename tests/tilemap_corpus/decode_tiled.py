#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""An independent reader of Tiled maps, for the corpus test.

Written from Tiled's format documentation (docs/reference/tmx-map-format.rst,
json-map-format.rst) and docs/semantics.org §7 and §9, not from the loader in
src/tilemap: the corpus test compares what this prints with what
downstroke-dump-map prints from ds::load_tilemap, map by map.

    decode_tiled.py [--parts=base,shapes,...] [--project=FILE.tiled-project] MAP

prints the canonical dump (see dump_format() below and README.org). Python 3
standard library, plus the zstandard module (Debian python3-zstandard) for
zstd-compressed layers.
"""
import base64
import gzip
import json
import os
import sys
import xml.etree.ElementTree as ET
import zlib

FLIP_BITS = 0xF0000000
GID_MASK = 0x0FFFFFFF
# The parts of the dump, in the order the dump prints them; `base` is what
# the loader read before issue 22, the others are switched on by --parts.
ALL_PARTS = ("base", "shapes", "templates", "nested-props", "tree", "tileset-extra")


class MapProblem(Exception):
    pass


# --- numbers and text as the dump writes them --------------------------------

def num(x):
    """A number as both dumpers print it: C's %.15g."""
    x = float(x)
    if x == 0:
        x = 0.0  # -0 prints as 0
    return "%.15g" % x


def quote(s):
    out = ['"']
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append("\\x%02x" % ord(ch))
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def truthy(text):
    return text.lower() == "true" or text == "1"


# --- properties ---------------------------------------------------------------

class Prop:
    def __init__(self, name, ptype, value, propertytype="", members=None, guessed=False):
        self.name, self.type, self.value = name, ptype, value
        self.propertytype = propertytype
        self.members = members or []
        self.guessed = guessed  # a JSON class member, its type read off its value


def scalar_text(ptype, value):
    """A scalar's value normalised so that TMX's text and JSON's value agree."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if ptype == "bool":
        return "true" if truthy(str(value)) else "false"
    if ptype in ("int", "object"):
        try:
            return str(int(float(value)))
        except ValueError:
            return str(value)
    if ptype == "float":
        try:
            return num(value)
        except ValueError:
            return str(value)
    if ptype == "color" and isinstance(value, str):
        return value.lower()
    return "" if value is None else str(value)


def xml_props(el):
    """The <properties> directly under el, in file order."""
    props = []
    holder = el.find("properties") if el is not None else None
    if holder is None:
        return props
    for p in holder.findall("property"):
        props.append(xml_prop(p))
    return props


def xml_prop(p):
    ptype = p.get("type", "string")
    name = p.get("name", "")
    if ptype == "class":
        return Prop(name, ptype, "", p.get("propertytype", ""), xml_props(p))
    if ptype == "list":
        items = [xml_prop(i) for i in p.findall("item")]  # a list's items are <item>s (Tiled 1.12)
        return Prop(name, ptype, "", p.get("propertytype", ""), items)
    value = p.get("value")
    if value is None:
        value = p.text or ""  # multi-line strings are the element's text
    return Prop(name, ptype, value, p.get("propertytype", ""))


def json_props(lst):
    return [json_prop(p) for p in (lst or [])]


def json_class_members(value):
    # A class's value is an object of member name → value; a member's type is
    # not written (only a project file knows it), so it is taken from the
    # JSON value: an object is a class, an array a list of typed items, true
    # and false a bool, a number with no fraction an int, any other number a
    # float, text a string (a color or file member reads as a string).
    members = []
    for k, v in (value or {}).items():
        members.append(json_value_prop(k, v))
    return members


def json_value_prop(name, v):
    if isinstance(v, dict):
        return Prop(name, "class", "", "", json_class_members(v), guessed=True)
    if isinstance(v, list):
        return Prop(name, "list", "", "", [json_item(i) for i in v], guessed=True)
    if isinstance(v, bool):
        return Prop(name, "bool", v, guessed=True)
    if isinstance(v, int) or (isinstance(v, float) and v.is_integer()):
        return Prop(name, "int", int(v), guessed=True)
    if isinstance(v, float):
        return Prop(name, "float", v, guessed=True)
    return Prop(name, "string", v, guessed=True)


def json_prop(p):
    ptype = p.get("type", "string")
    name = p.get("name", "")
    if ptype == "class":
        return Prop(name, ptype, "", p.get("propertytype", ""), json_class_members(p.get("value")))
    if ptype == "list":
        items = [json_item(i) for i in (p.get("value") or [])]
        return Prop(name, ptype, "", p.get("propertytype", ""), items)
    return Prop(name, ptype, p.get("value"), p.get("propertytype", ""))


def json_item(i):
    if isinstance(i, dict) and "type" in i:
        i = dict(i)
        i.setdefault("name", "")
        return json_prop(i)
    return json_value_prop("", i)


def prop_lines(props, indent, parts):
    lines = []
    for p in props:
        if p.type in ("class", "list"):
            if "nested-props" not in parts:
                continue
            head = "%sproperty %s %s" % (indent, quote(p.name), p.type)
            if p.propertytype:
                head += " propertytype=" + quote(p.propertytype)
            lines.append(head)
            lines += prop_lines(p.members, indent + "  ", parts)
        else:
            lines.append("%sproperty %s %s %s" % (indent, quote(p.name), p.type,
                                                  quote(scalar_text(p.type, p.value))))
    return lines


def find_prop(props, name):
    for p in props:
        if p.name == name:
            return p
    return None


def prop_true(p):
    return p is not None and scalar_text("bool", p.value) == "true"


# --- a Tiled project's class defaults ----------------------------------------

def read_project(path):
    """The class types of a Tiled project file (JSON "propertyTypes"): name
    → [(member name, type, default value, propertyType)], in the project's
    order."""
    with open(path, "rb") as f:
        doc = json.loads(f.read().decode("utf-8"))
    classes = {}
    for t in doc.get("propertyTypes", []):
        if t.get("type") == "class":
            classes[t["name"]] = [(mb["name"], mb.get("type", "string"), mb.get("value"),
                                   mb.get("propertyType", "")) for mb in t.get("members", [])]
    return classes


def default_prop(name, ptype, value, propertytype):
    if ptype == "class":
        return Prop(name, "class", "", propertytype, json_class_members(value))
    if ptype == "list":
        return Prop(name, "list", "", propertytype, [json_item(i) for i in (value or [])])
    return Prop(name, ptype, value, propertytype)


def fill_defaults(props, classes):
    """Tiled writes only the members of a class that differ from its type's
    defaults: each class property gets the rest from the project, in the
    class's member order, the members the class does not define after them;
    a member whose type JSON could not tell takes the class's; a class
    member's own default (some of its type's members) comes before its
    type's. Inside classes and lists too."""
    for p in props:
        if p.type == "list":
            fill_defaults(p.members, classes)
        if p.type != "class" or getattr(p, "filled", False):
            continue
        p.filled = True
        members = classes.get(p.propertytype)
        if members is None:
            fill_defaults(p.members, classes)
            continue
        have = {q.name: q for q in p.members}
        out = []
        for name, ptype, value, ptt in members:
            q = have.pop(name, None)
            if q is None:
                q = default_prop(name, ptype, value, ptt)
            else:
                if q.guessed:
                    q.type = ptype
                    if ptt:
                        q.propertytype = ptt
                if ptype == "class" and isinstance(value, dict):
                    # The member's own default (a class member may set some
                    # of its type's members) under what the map set.
                    set_here = {r.name for r in q.members}
                    q.members += [r for r in json_class_members(value) if r.name not in set_here]
            out.append(q)
        out += [q for q in p.members if q.name in have]
        p.members = out
        fill_defaults(p.members, classes)


def fill_map_defaults(m, classes):
    lists = [m.props] + [l["props"] for l in m.tile_layers]
    for ol in m.object_layers:
        lists.append(ol["props"])
        lists += [o["props"] for o in ol["objects"]]
    stack = list(m.tree)
    while stack:
        e = stack.pop()
        lists.append(e["props"])
        stack += e.get("children", [])
    for ts in m.tilesets:
        lists.append(ts["props"])
        lists += [t["props"] for t in ts["tiles"].values()]
    for props in lists:
        fill_defaults(props, classes)


# --- layer data ---------------------------------------------------------------

def gids_from_bytes(raw, count, what):
    if len(raw) != 4 * count:
        raise MapProblem("%s: %d bytes of layer data for %d cells" % (what, len(raw), count))
    return [int.from_bytes(raw[i:i + 4], "little") for i in range(0, len(raw), 4)]


def inflate(raw, compression, what):
    if compression in (None, ""):
        return raw
    if compression == "zlib":
        return zlib.decompress(raw)
    if compression == "gzip":
        return gzip.decompress(raw)
    if compression == "zstd":
        import zstandard  # only maps that use it need it
        return zstandard.ZstdDecompressor().decompressobj().decompress(raw)
    raise MapProblem("%s: unknown compression %r" % (what, compression))


def decode_text(text, encoding, compression, count, what):
    if encoding == "csv":
        items = [t.strip() for t in text.replace("\n", ",").split(",")]
        gids = [int(t) for t in items if t]
        if len(gids) != count:
            raise MapProblem("%s: %d gids for %d cells" % (what, len(gids), count))
        return gids
    if encoding == "base64":
        raw = base64.b64decode("".join(text.split()))
        return gids_from_bytes(inflate(raw, compression, what), count, what)
    raise MapProblem("%s: unknown encoding %r" % (what, encoding))


def decode_xml_data(el, encoding, compression, count, what):
    if encoding is None:
        gids = [int(t.get("gid", "0")) for t in el.findall("tile")]
        if len(gids) != count:
            raise MapProblem("%s: %d <tile> for %d cells" % (what, len(gids), count))
        return gids
    return decode_text(el.text or "", encoding, compression, count, what)


def decode_json_data(data, encoding, compression, count, what):
    if isinstance(data, list):
        if len(data) != count:
            raise MapProblem("%s: %d gids for %d cells" % (what, len(data), count))
        return [int(g) for g in data]
    return decode_text(data, encoding or "base64", compression, count, what)


class Chunk:
    def __init__(self, x, y, w, h, gids):
        self.x, self.y, self.w, self.h, self.gids = x, y, w, h, gids


def paste_chunks(layer, chunks):
    """An infinite layer: its chunks over their bounding box."""
    layer["pieces"] = chunks
    chunks = [c for c in chunks if c.w > 0 and c.h > 0]
    if not chunks:
        layer.update(col=0, row=0, w=0, h=0, cells=[])
        return
    c0 = min(c.x for c in chunks)
    r0 = min(c.y for c in chunks)
    c1 = max(c.x + c.w for c in chunks)
    r1 = max(c.y + c.h for c in chunks)
    w, h = c1 - c0, r1 - r0
    cells = [0] * (w * h)
    for c in chunks:
        for r in range(c.h):
            for col in range(c.w):
                cells[(c.y - r0 + r) * w + (c.x - c0 + col)] = c.gids[r * c.w + col]
    layer.update(col=c0, row=r0, w=w, h=h, cells=cells)


# --- files --------------------------------------------------------------------

def load_any(path):
    """('xml', root element) or ('json', object), told apart by content."""
    with open(path, "rb") as f:
        raw = f.read()
    head = raw.lstrip()[:1]
    if head in (b"{", b"["):
        return "json", json.loads(raw.decode("utf-8"))
    return "xml", ET.fromstring(raw)


def rel(base_file, path):
    return os.path.normpath(os.path.join(os.path.dirname(base_file), path))


# --- tilesets -----------------------------------------------------------------

def tile_from_xml(t):
    og = t.find("objectgroup")
    img = t.find("image")
    anim = t.find("animation")
    return {
        "id": int(t.get("id", "0")),
        "type": type_or_class(t.get("type"), t.get("class")),
        "props": xml_props(t),
        "shapes": og is not None and og.find("object") is not None,
        "image": img.get("source", "") if img is not None else "",
        "anim": [(int(fr.get("tileid")), int(fr.get("duration"))) for fr in anim.findall("frame")]
        if anim is not None else [],
    }


def tileset_from_xml(el, firstgid, source):
    img = el.find("image")
    off = el.find("tileoffset")
    return {
        "firstgid": firstgid, "source": source, "name": el.get("name", ""),
        "tw": int(el.get("tilewidth", "0")), "th": int(el.get("tileheight", "0")),
        "count": int(el.get("tilecount", "0")), "columns": int(el.get("columns", "0")),
        "margin": int(el.get("margin", "0")), "spacing": int(el.get("spacing", "0")),
        "image": img.get("source", "") if img is not None else "",
        "type": el.get("class", ""), "props": xml_props(el),
        "offset": (int(off.get("x", "0")), int(off.get("y", "0"))) if off is not None else (0, 0),
        "tiles": {t["id"]: t for t in map(tile_from_xml, el.findall("tile"))},
    }


def tile_from_json(t):
    og = t.get("objectgroup")
    return {
        "id": int(t.get("id", 0)),
        "type": type_or_class(t.get("type"), t.get("class")),
        "props": json_props(t.get("properties")),
        "shapes": bool(og and og.get("objects")),
        "image": t.get("image", ""),
        "anim": [(int(fr["tileid"]), int(fr["duration"])) for fr in t.get("animation", [])],
    }


def tileset_from_json(o, firstgid, source):
    return {
        "firstgid": firstgid, "source": source, "name": o.get("name", ""),
        "tw": int(o.get("tilewidth", 0)), "th": int(o.get("tileheight", 0)),
        "count": int(o.get("tilecount", 0)), "columns": int(o.get("columns", 0)),
        "margin": int(o.get("margin", 0)), "spacing": int(o.get("spacing", 0)),
        "image": o.get("image", ""), "type": o.get("class", ""),
        "props": json_props(o.get("properties")),
        "offset": (int(o.get("tileoffset", {}).get("x", 0)), int(o.get("tileoffset", {}).get("y", 0))),
        "tiles": {t["id"]: t for t in map(tile_from_json, o.get("tiles", []))},
    }


def external_tileset(map_path, source, firstgid):
    kind, doc = load_any(rel(map_path, source))
    if kind == "json":
        return tileset_from_json(doc, firstgid, source)
    return tileset_from_xml(doc, firstgid, source)


def tile_solid(tile):
    """Solid, wholly or by a shape: a true solid/collision/collides property, or
    collision shapes on a tile that is not one-way (a one-way tile's shapes make
    a one-way shape, semantics §12)."""
    if tile is None:
        return False
    if any(prop_true(find_prop(tile["props"], n)) for n in ("solid", "collision", "collides")):
        return True
    return bool(tile["shapes"]) and not tile_one_way(tile)


def tile_one_way(tile):
    return tile is not None and prop_true(find_prop(tile["props"], "one-way"))


# --- the map model this script builds -----------------------------------------

class Map:
    def __init__(self, path):
        self.path = path
        self.tilesets = []
        self.tile_layers = []    # flattened, with combined visibility/opacity
        self.object_layers = []  # flattened
        self.tree = []           # nested layer entries
        self.props = []

    def tileset_for(self, gid):
        gid &= GID_MASK
        best = None
        for ts in self.tilesets:
            if ts["firstgid"] <= gid and (best is None or ts["firstgid"] > best["firstgid"]):
                best = ts
        return best

    def tile_of(self, gid):
        ts = self.tileset_for(gid)
        if ts is None:
            return None
        return ts["tiles"].get((gid & GID_MASK) - ts["firstgid"])

    def gid_kind(self, gid):
        """'#' solid, '=' one-way, '.' neither (semantics §7, §9)."""
        if gid & GID_MASK == 0:
            return "."
        t = self.tile_of(gid)
        if tile_solid(t):
            return "#"
        if tile_one_way(t):
            return "="
        return "."


def has_tile(ts, local):
    """Whether a tileset has local tile id `local`: any id when its tilecount
    is unknown (0); in an image collection (no picture of its own, tiles
    with pictures) only the ids of its tiles, which may have gaps; else an
    id below tilecount."""
    if ts["count"] == 0:
        return True
    if not ts["image"] and any(t["image"] for t in ts["tiles"].values()):
        return local in ts["tiles"]
    return local < ts["count"]


def unknown_gids(m):
    """Per tile layer with gids beyond every tileset: (layer name, the first
    such raw gid in file order, its col, row, how many cells)."""
    out = []
    for l in m.tile_layers:
        first, count = None, 0
        for c in l.get("pieces", []):
            for i, raw in enumerate(c.gids):
                gid = raw & GID_MASK
                if gid == 0:
                    continue
                ts = m.tileset_for(gid)
                if ts is not None and has_tile(ts, gid - ts["firstgid"]):
                    continue
                count += 1
                if first is None:
                    first = (raw, c.x + i % c.w, c.y + i // c.w)
        if count:
            out.append((l["name"], first[0], first[1], first[2], count))
    return out


def layer_solidity(props):
    p = find_prop(props, "solid")
    if p is None:
        p = find_prop(props, "collision")
    if p is None:
        return "tiles"
    return "all" if prop_true(p) else "none"


# --- objects and templates ----------------------------------------------------

def type_or_class(type_, class_):
    """An object's or tile's type: type= (Tiled up to 1.8, and again from
    1.10), else class= (Tiled 1.9); semantics §7, "type or class"."""
    return type_ if type_ else (class_ or "")


OBJECT_FIELDS = ("id", "name", "type", "x", "y", "width", "height", "rotation", "visible", "gid")


def object_from_xml(o):
    obj = {"props": xml_props(o)}
    for k in ("id", "name", "x", "y", "width", "height", "rotation", "gid"):
        if o.get(k) is not None:
            obj[k] = o.get(k)
    if o.get("class") is not None or o.get("type") is not None:
        obj["type"] = type_or_class(o.get("type"), o.get("class"))
    if o.get("visible") is not None:
        obj["visible"] = truthy(o.get("visible"))
    if o.get("template") is not None:
        obj["template"] = o.get("template")
    for shape in ("ellipse", "capsule", "point"):
        if o.find(shape) is not None:
            obj["shape"] = shape
    for shape in ("polygon", "polyline"):
        e = o.find(shape)
        if e is not None:
            obj["shape"] = shape
            pts = []
            for pair in e.get("points", "").split():
                x, y = pair.split(",")
                pts.append((float(x), float(y)))
            obj["points"] = pts
    if o.find("text") is not None:
        obj["shape"] = "text"
        obj["text"] = o.find("text").text or ""
    return obj


def object_from_json(o):
    obj = {"props": json_props(o.get("properties"))}
    for k in ("id", "name", "x", "y", "width", "height", "rotation", "gid", "visible", "template"):
        if k in o:
            obj[k] = o[k]
    if "class" in o or "type" in o:
        obj["type"] = type_or_class(o.get("type"), o.get("class"))
    if o.get("ellipse"):
        obj["shape"] = "ellipse"
    if o.get("capsule"):
        obj["shape"] = "capsule"
    if o.get("point"):
        obj["shape"] = "point"
    for shape in ("polygon", "polyline"):
        if shape in o:
            obj["shape"] = shape
            obj["points"] = [(float(p["x"]), float(p["y"])) for p in o[shape]]
    if "text" in o:
        obj["shape"] = "text"
        obj["text"] = o["text"].get("text", "")
    return obj


def read_template(m, path):
    """A template's object, its gid moved into the map's gid space."""
    kind, doc = load_any(path)
    if kind == "json":
        obj = object_from_json(doc.get("object", {}))
        tsref = doc.get("tileset")
        ts_first, ts_source = (tsref.get("firstgid", 1), tsref.get("source")) if tsref else (1, None)
    else:
        obj = object_from_xml(doc.find("object"))
        tsel = doc.find("tileset")
        ts_first, ts_source = (int(tsel.get("firstgid", "1")), tsel.get("source")) if tsel is not None else (1, None)
    if "gid" in obj and ts_source:
        ts = template_tileset(m, rel(path, ts_source))
        raw = int(obj["gid"])
        obj["gid"] = ((raw & GID_MASK) - ts_first + ts["firstgid"]) | (raw & FLIP_BITS)
    return obj


def template_tileset(m, ts_path):
    """The map's tileset read from the file a template's tileset names; when
    the map has none from that file (its tilesets are embedded, or other
    files), that file joins the map's tilesets after the last gid in use, as
    Tiled adds a template's tileset to the map it is used in."""
    want = os.path.normpath(ts_path)
    for ts in m.tilesets:
        if ts["source"] and os.path.normpath(rel(m.path, ts["source"])) == want:
            return ts
    end = 1
    for ts in m.tilesets:
        ids = max(ts["tiles"]) + 1 if ts["tiles"] else 0
        end = max(end, ts["firstgid"] + max(ts["count"], ids))
    ts = external_tileset(m.path, os.path.relpath(want, os.path.dirname(m.path) or "."), end)
    m.tilesets.append(ts)
    return ts


def resolve_template(m, obj):
    """As Tiled resolves it (libtiled's readObject, syncWithTemplate): the
    position is the instance's alone; its name and class when not empty, its
    size when both sides are positive, its gid when not 0, whatever else it
    writes; the template's properties, each replaced by the instance's of
    that name, then the instance's others."""
    base = read_template(m, rel(m.path, obj["template"]))
    out = dict(base)
    out["x"], out["y"] = obj.get("x", 0), obj.get("y", 0)
    for k in ("name", "type"):
        if obj.get(k):
            out[k] = obj[k]
    if float(obj.get("width", 0)) > 0 and float(obj.get("height", 0)) > 0:
        out["width"], out["height"] = obj["width"], obj["height"]
    if int(obj.get("gid", 0) or 0):
        out["gid"] = obj["gid"]
    if "shape" in obj:
        out.pop("points", None)
    for k, v in obj.items():
        if k not in ("props", "x", "y", "name", "type", "width", "height", "gid"):
            out[k] = v
    props = list(base["props"])
    for p in obj["props"]:
        same = [i for i, q in enumerate(props) if q.name == p.name]
        if same:
            props[same[0]] = p  # an instance's value takes the template's place
        else:
            props.append(p)
    out["props"] = props
    return out


def finish_object(m, obj, parts):
    if "template" in obj and "templates" in parts:
        obj = resolve_template(m, obj)
    if "shape" not in obj:
        obj["shape"] = "tile" if int(obj.get("gid", 0) or 0) else "rect"
    return obj


def inherit_from_tiles(m):
    """Tiled's effective class of a tile object: with no class of its own it
    shows its tile's, and the tile's properties under its own (its own value
    of a name wins; its other properties follow the tile's)."""
    for ol in m.object_layers:
        for obj in ol["objects"]:
            gid = int(obj.get("gid", 0) or 0) & GID_MASK
            tile = m.tile_of(gid) if gid else None
            if tile is None:
                continue
            if not obj.get("type"):
                obj["type"] = tile["type"]
            own = {p.name: p for p in obj["props"]}
            merged = [own.pop(p.name, p) for p in tile["props"]]
            obj["props"] = merged + [p for p in obj["props"] if p.name in own]


# --- reading a map ------------------------------------------------------------

def read_xml_map(path, root, parts):
    m = Map(path)
    m.width, m.height = int(root.get("width", "0")), int(root.get("height", "0"))
    m.tw, m.th = int(root.get("tilewidth", "0")), int(root.get("tileheight", "0"))
    m.infinite = truthy(root.get("infinite", "0"))
    m.type, m.background = root.get("class", ""), root.get("backgroundcolor", "")
    m.props = xml_props(root)
    for ts in root.findall("tileset"):
        first = int(ts.get("firstgid", "1"))
        if ts.get("source"):
            m.tilesets.append(external_tileset(path, ts.get("source"), first))
        else:
            m.tilesets.append(tileset_from_xml(ts, first, ""))
    m.tree = read_xml_layers(m, root, True, 1.0, 0.0, 0.0, parts)
    return m


def common_xml_layer(el, kind):
    return {
        "kind": kind, "id": int(el.get("id", "0")), "name": el.get("name", ""),
        "type": el.get("class", ""), "visible": truthy(el.get("visible", "1")),
        "opacity": float(el.get("opacity", "1")),
        "offset": (float(el.get("offsetx", "0")), float(el.get("offsety", "0"))),
        "parallax": (float(el.get("parallaxx", "1")), float(el.get("parallaxy", "1"))),
        "tint": el.get("tintcolor", ""), "props": xml_props(el),
    }


def read_xml_layers(m, parent, vis, opac, ox, oy, parts):
    tree = []
    for el in parent:
        if el.tag == "layer":
            info = common_xml_layer(el, "tile")
            layer = {"name": info["name"], "props": info["props"],
                     "visible": vis and info["visible"], "opacity": opac * info["opacity"],
                     "offset": (ox + info["offset"][0], oy + info["offset"][1])}
            data = el.find("data")
            enc, comp = data.get("encoding"), data.get("compression")
            what = "layer " + quote(info["name"])
            if m.infinite:
                chunks = []
                for c in data.findall("chunk"):
                    w, h = int(c.get("width")), int(c.get("height"))
                    chunks.append(Chunk(int(c.get("x")), int(c.get("y")), w, h,
                                        decode_xml_data(c, enc, comp, w * h, what)))
                paste_chunks(layer, chunks)
            else:
                w, h = int(el.get("width", m.width)), int(el.get("height", m.height))
                layer.update(col=0, row=0, w=w, h=h,
                             cells=decode_xml_data(data, enc, comp, w * h, what))
                layer["pieces"] = [Chunk(0, 0, w, h, layer["cells"])]
            info["index"] = len(m.tile_layers)
            m.tile_layers.append(layer)
            tree.append(info)
        elif el.tag == "objectgroup":
            info = common_xml_layer(el, "object")
            objs = [finish_object(m, object_from_xml(o), parts) for o in el.findall("object")]
            info["index"] = len(m.object_layers)
            m.object_layers.append({"name": info["name"], "props": info["props"], "objects": objs})
            tree.append(info)
        elif el.tag == "imagelayer":
            info = common_xml_layer(el, "image")
            img = el.find("image")
            info["image"] = img.get("source", "") if img is not None else ""
            info["repeat"] = (truthy(el.get("repeatx", "0")), truthy(el.get("repeaty", "0")))
            tree.append(info)
        elif el.tag == "group":
            info = common_xml_layer(el, "group")
            info["children"] = read_xml_layers(
                m, el, vis and info["visible"], opac * info["opacity"],
                ox + info["offset"][0], oy + info["offset"][1], parts)
            tree.append(info)
    return tree


def read_json_map(path, doc, parts):
    m = Map(path)
    m.width, m.height = int(doc.get("width", 0)), int(doc.get("height", 0))
    m.tw, m.th = int(doc.get("tilewidth", 0)), int(doc.get("tileheight", 0))
    m.infinite = bool(doc.get("infinite", False))
    m.type, m.background = doc.get("class", ""), doc.get("backgroundcolor", "")
    m.props = json_props(doc.get("properties"))
    for ts in doc.get("tilesets", []):
        first = int(ts.get("firstgid", 1))
        if "source" in ts:
            m.tilesets.append(external_tileset(path, ts["source"], first))
        else:
            m.tilesets.append(tileset_from_json(ts, first, ""))
    m.tree = read_json_layers(m, doc.get("layers", []), True, 1.0, 0.0, 0.0, parts)
    return m


def common_json_layer(o, kind):
    return {
        "kind": kind, "id": int(o.get("id", 0)), "name": o.get("name", ""),
        "type": o.get("class", ""), "visible": bool(o.get("visible", True)),
        "opacity": float(o.get("opacity", 1)),
        "offset": (float(o.get("offsetx", 0)), float(o.get("offsety", 0))),
        "parallax": (float(o.get("parallaxx", 1)), float(o.get("parallaxy", 1))),
        "tint": o.get("tintcolor", ""), "props": json_props(o.get("properties")),
    }


def read_json_layers(m, layers, vis, opac, ox, oy, parts):
    tree = []
    for o in layers:
        t = o.get("type")
        if t == "tilelayer":
            info = common_json_layer(o, "tile")
            layer = {"name": info["name"], "props": info["props"],
                     "visible": vis and info["visible"], "opacity": opac * info["opacity"],
                     "offset": (ox + info["offset"][0], oy + info["offset"][1])}
            enc, comp = o.get("encoding", "csv"), o.get("compression", "")
            what = "layer " + quote(info["name"])
            if "chunks" in o:
                chunks = [Chunk(int(c["x"]), int(c["y"]), int(c["width"]), int(c["height"]),
                                decode_json_data(c["data"], enc, comp, int(c["width"]) * int(c["height"]), what))
                          for c in o["chunks"]]
                paste_chunks(layer, chunks)
            else:
                w, h = int(o.get("width", m.width)), int(o.get("height", m.height))
                layer.update(col=0, row=0, w=w, h=h,
                             cells=decode_json_data(o.get("data", []), enc, comp, w * h, what))
                layer["pieces"] = [Chunk(0, 0, w, h, layer["cells"])]
            info["index"] = len(m.tile_layers)
            m.tile_layers.append(layer)
            tree.append(info)
        elif t == "objectgroup":
            info = common_json_layer(o, "object")
            objs = [finish_object(m, object_from_json(x), parts) for x in o.get("objects", [])]
            info["index"] = len(m.object_layers)
            m.object_layers.append({"name": info["name"], "props": info["props"], "objects": objs})
            tree.append(info)
        elif t == "imagelayer":
            info = common_json_layer(o, "image")
            info["image"] = o.get("image", "")
            info["repeat"] = (bool(o.get("repeatx", False)), bool(o.get("repeaty", False)))
            tree.append(info)
        elif t == "group":
            info = common_json_layer(o, "group")
            info["children"] = read_json_layers(
                m, o.get("layers", []), vis and info["visible"], opac * info["opacity"],
                ox + info["offset"][0], oy + info["offset"][1], parts)
            tree.append(info)
    return tree


def read_map(path, parts, project=None):
    kind, doc = load_any(path)
    m = read_json_map(path, doc, parts) if kind == "json" else read_xml_map(path, doc, parts)
    m.tilesets.sort(key=lambda ts: ts["firstgid"])
    inherit_from_tiles(m)
    if project:
        fill_map_defaults(m, read_project(project))
    if m.infinite:
        live = [l for l in m.tile_layers if l["w"] > 0 and l["h"] > 0]
        if live:
            c0 = min(l["col"] for l in live)
            r0 = min(l["row"] for l in live)
            m.width = max(l["col"] + l["w"] for l in live) - c0
            m.height = max(l["row"] + l["h"] for l in live) - r0
        else:
            m.width = m.height = 0
    return m


# --- the dump -----------------------------------------------------------------

def grid_lines(m):
    live = [l for l in m.tile_layers if l["w"] > 0 and l["h"] > 0]
    if not live:
        return ["grid origin=0,0 size=0x0"]
    c0 = min(l["col"] for l in live)
    r0 = min(l["row"] for l in live)
    c1 = max(l["col"] + l["w"] for l in live)
    r1 = max(l["row"] + l["h"] for l in live)
    lines = ["grid origin=%d,%d size=%dx%d" % (c0, r0, c1 - c0, r1 - r0)]
    for row in range(r0, r1):
        chars = []
        for col in range(c0, c1):
            solid = one_way = False
            for l in live:
                mode = layer_solidity(l["props"])
                c, r = col - l["col"], row - l["row"]
                if mode == "none" or not (0 <= c < l["w"] and 0 <= r < l["h"]):
                    continue
                gid = l["cells"][r * l["w"] + c]
                if gid & GID_MASK == 0:
                    continue
                kind = "#" if mode == "all" else m.gid_kind(gid)
                solid = solid or kind == "#"
                one_way = one_way or kind == "="
            chars.append("#" if solid else "=" if one_way else ".")
        lines.append("  " + "".join(chars))
    return lines


def tile_lines(ts, parts):
    lines = []
    for tid in sorted(ts["tiles"]):
        t = ts["tiles"][tid]
        anim = "tileset-extra" in parts and t["anim"]
        if not (t["type"] or t["props"] or t["shapes"] or t["image"] or anim):
            continue
        line = "  tile %d type=%s shapes=%d image=%s" % (tid, quote(t["type"]), int(t["shapes"]), quote(t["image"]))
        lines.append(line)
        if anim:
            lines.append("    animation " + " ".join("%d:%d" % fr for fr in t["anim"]))
        lines += prop_lines(t["props"], "    ", parts)
    return lines


def tree_lines(entries, indent, parts):
    lines = []
    for e in entries:
        line = "%s%s %s id=%d type=%s visible=%d opacity=%s offset=%s,%s parallax=%s,%s tint=%s" % (
            indent, e["kind"], quote(e["name"]), e["id"], quote(e["type"]), int(e["visible"]),
            num(e["opacity"]), num(e["offset"][0]), num(e["offset"][1]),
            num(e["parallax"][0]), num(e["parallax"][1]), quote(e["tint"].lower()))
        if e["kind"] in ("tile", "object"):
            line += " index=%d" % e["index"]
        if e["kind"] == "image":
            line += " image=%s repeat=%d,%d" % (quote(e["image"]), int(e["repeat"][0]), int(e["repeat"][1]))
        lines.append(line)
        lines += prop_lines(e["props"], indent + "  ", parts)
        lines += tree_lines(e.get("children", []), indent + "  ", parts)
    return lines


def object_lines(obj, parts):
    line = "  object id=%d name=%s type=%s x=%s y=%s w=%s h=%s rot=%s visible=%d gid=%d" % (
        int(obj.get("id", 0)), quote(obj.get("name", "")), quote(obj.get("type", "")),
        num(obj.get("x", 0)), num(obj.get("y", 0)), num(obj.get("width", 0)), num(obj.get("height", 0)),
        num(obj.get("rotation", 0)), int(bool(obj.get("visible", True))), int(obj.get("gid", 0) or 0))
    lines = [line]
    if "shapes" in parts:
        shape = "  shape " + obj["shape"]
        if obj.get("points"):
            shape += " " + " ".join("%s,%s" % (num(x), num(y)) for x, y in obj["points"])
        if obj["shape"] == "text":
            shape += " " + quote(obj.get("text", ""))
        lines.append("  " + shape)
    lines += prop_lines(obj["props"], "    ", parts)
    return lines


def dump(m, parts):
    out = ["map %dx%d tile %dx%d infinite %d" % (m.width, m.height, m.tw, m.th, int(m.infinite))]
    if "tileset-extra" in parts:
        out.append("map-class %s background=%s" % (quote(m.type), quote(m.background.lower())))
    out += prop_lines(m.props, "  ", parts)
    for ts in m.tilesets:
        out.append("tileset firstgid=%d name=%s tile=%dx%d count=%d columns=%d margin=%d spacing=%d image=%s" % (
            ts["firstgid"], quote(ts["name"]), ts["tw"], ts["th"], ts["count"], ts["columns"],
            ts["margin"], ts["spacing"], quote(ts["image"])))
        if "tileset-extra" in parts:
            out.append("  class=%s tileoffset=%d,%d" % (quote(ts["type"]), ts["offset"][0], ts["offset"][1]))
            out += prop_lines(ts["props"], "  ", parts)
        out += tile_lines(ts, parts)
    for l in m.tile_layers:
        line = "layer %s origin=%d,%d size=%dx%d visible=%d opacity=%s solidity=%s" % (
            quote(l["name"]), l["col"], l["row"], l["w"], l["h"], int(l["visible"]),
            num(l["opacity"]), layer_solidity(l["props"]))
        if "tileset-extra" in parts:
            line += " offset=%s,%s" % (num(l["offset"][0]), num(l["offset"][1]))
        out.append(line)
        out += prop_lines(l["props"], "  ", parts)
        for r in range(l["h"]):
            out.append("  " + " ".join(str(g) for g in l["cells"][r * l["w"]:(r + 1) * l["w"]]))
    out += grid_lines(m)
    for ol in m.object_layers:
        out.append("objects %s" % quote(ol["name"]))
        out += prop_lines(ol["props"], "  ", parts)
        for obj in ol["objects"]:
            out += object_lines(obj, parts)
    if "tree" in parts:
        out.append("tree")
        out += tree_lines(m.tree, "  ", parts)
    return out


def parse_parts(text):
    parts = {"base"} | {p for p in text.split(",") if p}
    unknown = parts - set(ALL_PARTS)
    if unknown:
        raise SystemExit("decode_tiled: unknown part(s) %s (known: %s)" % (
            ", ".join(sorted(unknown)), ", ".join(ALL_PARTS)))
    return parts


def main(argv):
    parts, project = {"base"}, None
    args = argv[1:]
    while args and args[0].startswith("--"):
        a = args.pop(0)
        if a.startswith("--parts="):
            parts = parse_parts(a[len("--parts="):])
        elif a.startswith("--project="):
            project = a[len("--project="):]
        else:
            raise SystemExit("decode_tiled: unknown option " + a)
    if len(args) != 1:
        raise SystemExit("usage: decode_tiled.py [--parts=base,shapes,...] [--project=FILE] MAP")
    m = read_map(args[0], parts, project)
    sys.stdout.reconfigure(encoding="utf-8")
    sys.stdout.write("\n".join(dump(m, parts)) + "\n")


if __name__ == "__main__":
    main(sys.argv)
