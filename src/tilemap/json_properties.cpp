// SPDX-License-Identifier: MIT
// json_properties.hpp: Tiled's JSON properties into the model's Property.
#include "json_properties.hpp"

#include "../constants.hpp"

namespace ds::json {

namespace {

Property read_list_item(const Node& item, int depth);

// Class and list members one level deeper than `depth`, as TMX bounds them.
void check_depth(const Node& v, int depth) {
    if (depth + 1 > kMaxPropertyDepth)
        v.fail("nests properties more than " + std::to_string(kMaxPropertyDepth) + " deep");
}

// The text a scalar keeps (Property::value): numbers as JSON writes them.
std::string number_text(const Node& v, const std::string& type) {
    if (type == "int" || type == "object") return std::to_string(v.integer());
    v.number();  // a finite number
    return v.value->dump();
}

// A class member as Tiled's JSON writes it: a bare value, whose Tiled type
// is inferred from its JSON type (a project file corrects it later).
Property read_member(const std::string& name, const Node& v, int depth) {
    Property p;
    p.name = name;
    if (v.value->is_string()) {
        p.value = v.string();
    } else if (v.value->is_boolean()) {
        p.type = "bool";
        p.value = v.boolean() ? "true" : "false";
    } else if (v.value->is_number()) {
        p.type = v.value->is_number_float() ? "float" : "int";
        p.value = number_text(v, p.type);
    } else if (v.value->is_object()) {
        p.type = "class";
        check_depth(v, depth);
        for (const auto& [key, member] : v.value->items())
            p.members.push_back(read_member(key, {&member, v.path + "." + key}, depth + 1));
    } else if (v.value->is_array() || v.value->is_binary()) {  // binary: a packed "data" array
        v.array();  // unpacks it
        p.type = "list";
        check_depth(v, depth);
        for (size_t i = 0; i < v.value->size(); ++i) p.members.push_back(read_list_item(v[i], depth + 1));
    } else {
        v.fail("is null, expected a member value");
    }
    return p;
}

// Value `v` of a property (or list item) of `type`, into p; `type_node`
// is where the type was written, named when it is none of Tiled's.
void read_value_of(const Node& v, const Node& type_node, const std::string& type, Property& p, int depth) {
    if (type == "string" || type == "color" || type == "file") {
        p.value = v.string();
    } else if (type == "int" || type == "float" || type == "object") {
        p.value = number_text(v, type);
    } else if (type == "bool") {
        p.value = v.boolean() ? "true" : "false";
    } else if (type == "class") {
        v.object();
        check_depth(v, depth);
        for (const auto& [key, member] : v.value->items())
            p.members.push_back(read_member(key, {&member, v.path + "." + key}, depth + 1));
    } else if (type == "list") {
        v.array();
        check_depth(v, depth);
        for (size_t i = 0; i < v.value->size(); ++i) p.members.push_back(read_list_item(v[i], depth + 1));
    } else {
        type_node.fail("is none of string, int, float, bool, color, file, object, class or list");
    }
}

// The value of a property (or list item) of `type`, into p.
void read_value(const Node& owner, const std::string& type, Property& p, int depth) {
    if (!owner.has("value")) return;  // Tiled leaves empty values out
    read_value_of(owner["value"], owner.has("type") ? owner["type"] : owner, type, p, depth);
}


}  // namespace

Property read_typed(const Node& n, std::string name, int depth) {
    n.object();
    Property p;
    p.name = std::move(name);
    p.type = json::string_or(n, "type", "string");
    // Maps write "propertytype", project files "propertyType".
    p.property_type = json::string_or(n, "propertytype");
    if (p.property_type.empty()) p.property_type = json::string_or(n, "propertyType");
    read_value(n, p.type, p, depth);
    return p;
}

namespace {
Property read_list_item(const Node& item, int depth) { return read_typed(item, "", depth); }
}  // namespace

// A value whose type is not given takes the type its JSON value has, as a
// class member's does; the names come in key order, as Tiled's QVariantMap
// gives them.
Properties read_property_object(const Node& values, const Node* types) {
    values.object();
    if (types) types->object();
    Properties out;
    for (const auto& [key, value] : values.value->items()) {
        const Node v{&value, values.path + "." + key};
        if (!types || !types->has(key.c_str())) {
            out.push_back(read_member(key, v, 0));
            continue;
        }
        const Node type_node = (*types)[key.c_str()];
        Property p;
        p.name = key;
        p.type = type_node.string();
        read_value_of(v, type_node, p.type, p, 0);
        out.push_back(std::move(p));
    }
    return out;
}

Properties read_properties(const Node& owner) {
    Properties out;
    if (!owner.has("properties")) return out;
    const Node list = owner["properties"];
    if (list.value->is_object()) {  // before Tiled 1.2
        if (!owner.has("propertytypes")) return read_property_object(list, nullptr);
        const Node types = owner["propertytypes"];
        return read_property_object(list, &types);
    }
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node p = list[i];
        p.object();
        out.push_back(read_typed(p, json::string_or(p, "name")));
    }
    return out;
}

}  // namespace ds::json
