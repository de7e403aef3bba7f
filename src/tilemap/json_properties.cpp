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

// The value of a property (or list item) of `type`, into p.
void read_value(const Node& owner, const std::string& type, Property& p, int depth) {
    if (!owner.has("value")) return;  // Tiled leaves empty values out
    const Node v = owner["value"];
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
        owner["type"].fail("is none of string, int, float, bool, color, file, object, class or list");
    }
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

Properties read_properties(const Node& owner) {
    Properties out;
    if (!owner.has("properties")) return out;
    const Node list = owner["properties"];
    for (size_t i = 0; i < list.array().size(); ++i) {
        const Node p = list[i];
        p.object();
        out.push_back(read_typed(p, json::string_or(p, "name")));
    }
    return out;
}

}  // namespace ds::json
