// SPDX-License-Identifier: MIT
// project.hpp: a Tiled project file's property types, and filling the class
// members a map leaves at their defaults.
#include "project.hpp"

#include <algorithm>

#include "json_properties.hpp"
#include "json_values.hpp"
#include "map_build.hpp"

namespace ds {

const PropertyClass* ProjectTypes::find_class(std::string_view name) const {
    for (const PropertyClass& c : classes)
        if (c.name == name) return &c;
    return nullptr;
}

namespace {

using json::Json;
using json::Node;

PropertyClass read_class(const Node& t, std::string name) {
    PropertyClass c;
    c.name = std::move(name);
    const Node members = t["members"];
    for (size_t i = 0; i < members.array().size(); ++i) {
        const Node m = members[i];
        m.object();
        c.members.push_back(json::read_typed(m, json::string_or(m, "name")));
    }
    return c;
}

ProjectTypes read_types(const Node& root, const std::string& path) {
    ProjectTypes types;
    types.path = path;
    const Json& list = json::array_or_empty(root, "propertyTypes");
    const Node all{&list, "propertyTypes"};
    for (size_t i = 0; i < list.size(); ++i) {
        const Node t = all[i];
        t.object();
        const std::string name = json::string_or(t, "name"), kind = json::string_or(t, "type");
        if (kind == "class")
            types.classes.push_back(t.has("members") ? read_class(t, name) : PropertyClass{name, {}});
        else if (kind == "enum")
            types.enums.push_back(name);
        else if (t.has("type"))
            t["type"].fail("is neither \"class\" nor \"enum\"");
        else
            t.fail("has no \"type\"");
    }
    return types;
}

// One fill over a map: its budget of members and the project it reads.
struct Filler {
    const ProjectTypes& types;
    int64_t filled = 0;

    [[noreturn]] void fail(const std::string& message) const {
        throw MapError(types.path, 0, message);
    }

    const PropertyClass& class_of(const Property& p, const std::string& where) const {
        const PropertyClass* c = types.find_class(p.property_type);
        if (!c)
            fail("class '" + p.property_type + "' of property '" + p.name + "' (" + where +
                 ") is not defined in the project");
        return *c;
    }

    void take(int64_t n) {
        filled += n;
        if (filled > kMaxFilledMembers)
            fail("filling class defaults needs more than " + std::to_string(kMaxFilledMembers) +
                 " members (kMaxFilledMembers)");
    }

    // A member the map wrote takes what the class says of its type when
    // the map could not tell (JSON writes bare values).
    static void adopt_type(const Property& def, Property& m) {
        if (m.property_type.empty()) m.property_type = def.property_type;
        const bool from_text = m.type == "string" && (def.type == "color" || def.type == "file");
        const bool from_int = m.type == "int" && (def.type == "float" || def.type == "object");
        if (from_text || from_int) m.type = def.type;
    }

    // A class member's own default (Spawn.inner = {"weight": 2.5}) comes
    // before its class's (Inner.weight = 0.5), as Tiled resolves it: what
    // the map leaves out of a member it wrote is taken from there first.
    void inherit_member_defaults(const Property& def, Property& m) {
        if (def.type != "class" || m.type != "class") return;
        for (const Property& d : def.members) {
            const bool written = std::any_of(m.members.begin(), m.members.end(),
                                             [&](const Property& x) { return x.name == d.name; });
            if (written) continue;
            take(1);
            m.members.push_back(d);
        }
    }

    void fill(Property& p, const std::string& where, int depth) {
        if (depth > kMaxJsonDepth)
            fail("class '" + p.property_type + "' nests itself more than " +
                 std::to_string(kMaxJsonDepth) + " deep (" + where + ")");
        if (p.type == "list") {
            for (Property& item : p.members) fill(item, where, depth + 1);
            return;
        }
        if (p.type != "class" || p.property_type.empty()) return;
        const PropertyClass& c = class_of(p, where);
        Properties out;
        for (const Property& def : c.members) {
            auto it = std::find_if(p.members.begin(), p.members.end(),
                                   [&](const Property& m) { return m.name == def.name; });
            if (it == p.members.end()) {
                take(1);
                out.push_back(def);
            } else {
                adopt_type(def, *it);
                inherit_member_defaults(def, *it);
                out.push_back(std::move(*it));
                p.members.erase(it);
            }
            fill(out.back(), where, depth + 1);
        }
        for (Property& rest : p.members) out.push_back(std::move(rest));
        p.members = std::move(out);
    }

    void fill_all(Properties& props, const std::string& where) {
        for (Property& p : props) fill(p, where, 0);
    }

    void fill_tree(std::vector<LayerInfo>& tree) {
        for (LayerInfo& l : tree) {
            fill_all(l.properties, "layer '" + l.name + "'");
            fill_tree(l.children);
        }
    }
};

}  // namespace

ProjectTypes parse_project(std::string_view text, const std::string& path) {
    try {
        const json::Json doc = json::parse(text, kMaxJsonDepth);
        if (!doc.is_object())
            throw json::JsonError("the document is " + json::describe(doc) + ", expected an object");
        return read_types({&doc, ""}, path);
    } catch (const json::JsonSyntaxError& e) {
        throw MapError(path, e.line, std::string(e.what()) + " (project file)");
    } catch (const json::JsonError& e) {
        throw MapError(path, 0, std::string(e.what()) + " (project file)");
    } catch (const json::Json::exception& e) {
        throw MapError(path, 0, std::string("unexpected JSON: ") + e.what() + " (project file)");
    }
}

void fill_class_defaults(Tilemap& map, const ProjectTypes& types) {
    Filler f{types};
    f.fill_all(map.properties, "the map");
    for (TileLayer& l : map.layers) f.fill_all(l.properties, "layer '" + l.name + "'");
    for (ObjectLayer& l : map.object_layers) {
        f.fill_all(l.properties, "layer '" + l.name + "'");
        for (MapObject& o : l.objects)
            f.fill_all(o.properties, "object " + std::to_string(o.id) + " of layer '" + l.name + "'");
    }
    f.fill_tree(map.layer_tree);
    for (Tileset& ts : map.tilesets) {
        f.fill_all(ts.properties, "tileset '" + ts.name + "'");
        for (TileInfo& t : ts.tiles) {
            const std::string where = "tile " + std::to_string(t.id) + " of tileset '" + ts.name + "'";
            f.fill_all(t.properties, where);
            for (MapObject& o : t.objects) f.fill_all(o.properties, "object of " + where);
        }
    }
}

namespace build {

void apply_project(LoadState& s, Tilemap& map) {
    const std::string& path = s.options.project_path;
    if (path.empty()) return;
    std::string error;
    const auto text = read_counted(s, path, error);
    if (!text) throw MapError(path, 0, "cannot open project file: " + error);
    fill_class_defaults(map, parse_project(*text, path));
}

}  // namespace build

}  // namespace ds
