// SPDX-License-Identifier: MIT
// downstroke-dump-map: loads a map with ds::load_tilemap and prints the
// corpus test's canonical dump of the model (tilemap.hpp) and its
// solid_grid(), line for line what decode_tiled.py prints from the file.
//
//   downstroke-dump-map [--parts=base,shapes,...] [--strict] [--project=FILE] MAP
//
// Exit status 0 with the dump on stdout; 1 with the loader's message on
// stderr when the map is refused; 2 on a bad command line.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tilemap/tilemap.hpp"

namespace {

using Parts = std::set<std::string>;
// The dump's parts beyond `base` (what the loader read before issue 22);
// decode_tiled.py's ALL_PARTS names the same.
const std::set<std::string> kKnownParts = {"base",   "shapes",       "templates",
                                           "nested-props", "tree", "tileset-extra"};

std::string num(double x) {
    if (x == 0) x = 0;  // -0 prints as 0
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.15g", x);
    return buf;
}

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (u < 0x20 || u == 0x7F) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", u);
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The value as decode_tiled.py normalises it, so that TMX's text and JSON's
// value text compare equal.
std::string scalar_text(const ds::Property& p) {
    if (p.type == "bool") return ds::property_is_true(p) ? "true" : "false";
    if (p.type == "int" || p.type == "object" || p.type == "float") {
        char* end = nullptr;
        const double d = std::strtod(p.value.c_str(), &end);
        if (p.value.empty() || *end != '\0') return p.value;
        if (p.type == "float") return num(d);
        return std::to_string(static_cast<long long>(d));
    }
    if (p.type == "color") return lower(p.value);
    return p.value;
}

void print_props(std::ostream& out, const ds::Properties& props, const std::string& indent,
                 const Parts& parts) {
    for (const ds::Property& p : props) {
        if (p.type == "class" || p.type == "list") {
            if (!parts.count("nested-props")) continue;
            out << indent << "property " << quote(p.name) << ' ' << p.type;
            if (!p.property_type.empty()) out << " propertytype=" << quote(p.property_type);
            out << '\n';
            print_props(out, p.members, indent + "  ", parts);
        } else {
            out << indent << "property " << quote(p.name) << ' ' << p.type << ' '
                << quote(scalar_text(p)) << '\n';
        }
    }
}

const char* solidity_name(ds::LayerSolidity s) {
    switch (s) {
        case ds::LayerSolidity::All: return "all";
        case ds::LayerSolidity::None: return "none";
        case ds::LayerSolidity::FromTiles: break;
    }
    return "tiles";
}

const char* shape_name(ds::ObjectShape s) {
    switch (s) {
        case ds::ObjectShape::Ellipse: return "ellipse";
        case ds::ObjectShape::Capsule: return "capsule";
        case ds::ObjectShape::Point: return "point";
        case ds::ObjectShape::Polygon: return "polygon";
        case ds::ObjectShape::Polyline: return "polyline";
        case ds::ObjectShape::Text: return "text";
        case ds::ObjectShape::Tile: return "tile";
        case ds::ObjectShape::Rectangle: break;
    }
    return "rect";
}

const char* kind_name(ds::LayerKind k) {
    switch (k) {
        case ds::LayerKind::Object: return "object";
        case ds::LayerKind::Image: return "image";
        case ds::LayerKind::Group: return "group";
        case ds::LayerKind::Tile: break;
    }
    return "tile";
}

void print_tilesets(std::ostream& out, const ds::Tilemap& m, const Parts& parts) {
    const bool extra = parts.count("tileset-extra") > 0;
    for (const ds::Tileset& ts : m.tilesets) {
        out << "tileset firstgid=" << ts.firstgid << " name=" << quote(ts.name) << " tile=" << ts.tile_width
            << 'x' << ts.tile_height << " count=" << ts.tile_count << " columns=" << ts.columns
            << " margin=" << ts.margin << " spacing=" << ts.spacing << " image=" << quote(ts.image) << '\n';
        if (extra) {
            out << "  class=" << quote(ts.type) << " tileoffset=" << ts.tile_offset_x << ','
                << ts.tile_offset_y << '\n';
            print_props(out, ts.properties, "  ", parts);
        }
        for (const ds::TileInfo& t : ts.tiles) {
            const bool anim = extra && !t.animation.empty();
            if (t.type.empty() && t.properties.empty() && !t.has_collision_shapes && t.image.empty() && !anim)
                continue;
            out << "  tile " << t.id << " type=" << quote(t.type) << " shapes=" << int{t.has_collision_shapes}
                << " image=" << quote(t.image) << '\n';
            if (anim) {
                out << "    animation";
                for (const ds::AnimationFrame& f : t.animation) out << ' ' << f.tile_id << ':' << f.duration_ms;
                out << '\n';
            }
            print_props(out, t.properties, "    ", parts);
        }
    }
}

void print_layers(std::ostream& out, const ds::Tilemap& m, const Parts& parts) {
    for (const ds::TileLayer& l : m.layers) {
        out << "layer " << quote(l.name) << " origin=" << l.origin_col << ',' << l.origin_row << " size="
            << l.width << 'x' << l.height << " visible=" << int{l.visible} << " opacity=" << num(l.opacity)
            << " solidity=" << solidity_name(l.solidity);
        if (parts.count("tileset-extra")) out << " offset=" << num(l.offset_x) << ',' << num(l.offset_y);
        out << '\n';
        print_props(out, l.properties, "  ", parts);
        for (int r = 0; r < l.height; ++r) {
            out << ' ';
            for (int c = 0; c < l.width; ++c) out << ' ' << l.cells[static_cast<size_t>(r) * l.width + c];
            out << '\n';
        }
    }
}

void print_grid(std::ostream& out, const ds::Tilemap& m) {
    const ds::TileGrid g = m.solid_grid();
    out << "grid origin=" << g.origin_col() << ',' << g.origin_row() << " size=" << g.cols() << 'x'
        << g.rows() << '\n';
    for (int r = 0; r < g.rows(); ++r) {
        out << "  ";
        for (int c = 0; c < g.cols(); ++c) {
            const uint8_t k = g.cell(g.origin_col() + c, g.origin_row() + r);
            // A shaped cell (semantics §12) as its family: solid or one-way.
            const ds::CellShape* s = g.shape(g.origin_col() + c, g.origin_row() + r);
            const bool solid = k == ds::kSolidCell || (s && !s->one_way);
            const bool one_way = k == ds::kOneWayCell || (s && s->one_way);
            out << (solid ? '#' : one_way ? '=' : '.');
        }
        out << '\n';
    }
}

void print_objects(std::ostream& out, const ds::Tilemap& m, const Parts& parts) {
    for (const ds::ObjectLayer& ol : m.object_layers) {
        out << "objects " << quote(ol.name) << '\n';
        print_props(out, ol.properties, "  ", parts);
        for (const ds::MapObject& o : ol.objects) {
            out << "  object id=" << o.id << " name=" << quote(o.name) << " type=" << quote(o.type)
                << " x=" << num(o.x) << " y=" << num(o.y) << " w=" << num(o.width) << " h=" << num(o.height)
                << " rot=" << num(o.rotation) << " visible=" << int{o.visible} << " gid=" << o.gid << '\n';
            if (parts.count("shapes")) {
                out << "    shape " << shape_name(o.shape);
                for (const ds::ObjectPoint& p : o.points) out << ' ' << num(p.x) << ',' << num(p.y);
                if (o.shape == ds::ObjectShape::Text) out << ' ' << quote(o.text.text);
                out << '\n';
            }
            print_props(out, o.properties, "    ", parts);
        }
    }
}

void print_tree(std::ostream& out, const std::vector<ds::LayerInfo>& tree, const std::string& indent,
                const Parts& parts) {
    for (const ds::LayerInfo& e : tree) {
        out << indent << kind_name(e.kind) << ' ' << quote(e.name) << " id=" << e.id << " type=" << quote(e.type)
            << " visible=" << int{e.visible} << " opacity=" << num(e.opacity) << " offset=" << num(e.offset_x)
            << ',' << num(e.offset_y) << " parallax=" << num(e.parallax_x) << ',' << num(e.parallax_y)
            << " tint=" << quote(lower(e.tint_color));
        if (e.kind == ds::LayerKind::Tile || e.kind == ds::LayerKind::Object) out << " index=" << e.index;
        if (e.kind == ds::LayerKind::Image)
            out << " image=" << quote(e.image) << " repeat=" << int{e.repeat_x} << ',' << int{e.repeat_y};
        out << '\n';
        print_props(out, e.properties, indent + "  ", parts);
        print_tree(out, e.children, indent + "  ", parts);
    }
}

std::string dump(const ds::Tilemap& m, const Parts& parts) {
    std::ostringstream out;
    out << "map " << m.width << 'x' << m.height << " tile " << m.tile_width << 'x' << m.tile_height
        << " infinite " << int{m.infinite} << '\n';
    if (parts.count("tileset-extra"))
        out << "map-class " << quote(m.type) << " background=" << quote(lower(m.background_color)) << '\n';
    print_props(out, m.properties, "  ", parts);
    print_tilesets(out, m, parts);
    print_layers(out, m, parts);
    print_grid(out, m);
    print_objects(out, m, parts);
    if (parts.count("tree")) {
        out << "tree\n";
        print_tree(out, m.layer_tree, "  ", parts);
    }
    return out.str();
}

bool parse_parts(const std::string& list, Parts& parts) {
    std::stringstream ss(list);
    for (std::string p; std::getline(ss, p, ',');) {
        if (p.empty()) continue;
        if (!kKnownParts.count(p)) {
            std::cerr << "downstroke-dump-map: unknown part '" << p << "'\n";
            return false;
        }
        parts.insert(p);
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Parts parts = {"base"};
    ds::LoadOptions options;
    std::string path;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a.rfind("--parts=", 0) == 0) {
            if (!parse_parts(a.substr(8), parts)) return 2;
        } else if (a == "--strict") {
            options.strict = true;
        } else if (a.rfind("--project=", 0) == 0) {
            options.project_path = a.substr(10);
        } else if (path.empty()) {
            path = a;
        } else {
            path.clear();
            break;
        }
    }
    if (path.empty()) {
        std::cerr << "usage: downstroke-dump-map [--parts=base,shapes,...] [--strict] [--project=FILE] MAP\n";
        return 2;
    }
    try {
        const ds::Tilemap m = ds::load_tilemap(path, options);
        std::cout << dump(m, parts);
        for (const std::string& w : m.warnings) std::cerr << "warning: " << w << '\n';
    } catch (const std::exception& e) {
        std::cerr << e.what() << '\n';
        return 1;
    }
    return 0;
}
