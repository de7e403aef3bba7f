// SPDX-License-Identifier: MIT
// json_values.hpp: typed access with messages that name the JSON path.
#include "json_values.hpp"

#include "json_dom.hpp"
#include "utf8.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

namespace ds::json {

namespace {

// Open brackets at the deepest point, strings skipped; stops past `max`.
bool deeper_than(std::string_view text, int max) {
    int depth = 0;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > max) return true;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

// nlohmann's byte count includes the character it stopped at: the line is
// that character's.
int stop_line(std::string_view text, size_t byte) { return tmx::line_at(text, byte > 0 ? byte - 1 : 0); }

// The 1-based column, in bytes, of the character nlohmann stopped at.
int stop_column(std::string_view text, size_t byte) {
    const size_t at = std::min(byte > 0 ? byte - 1 : 0, text.size());
    size_t start = at;
    while (start > 0 && text[start - 1] != '\n') --start;
    return int(std::min<size_t>(at - start + 1, INT_MAX));
}

// nlohmann's what() starts with its id ("[json.exception.parse_error.101] ")
// and, for parse errors, the position, which the MapError says itself:
// keep the reason only. Whatever nlohmann quotes of the text goes too —
// "; last read: '…'" (the bytes of the token it stopped in, with what came
// after it) and "parsing '…'" (a number too large): the file can be any a
// map names (a tileset's "../../" source), and its contents are not the
// error's to show. The line and column say where to look.
std::string reason(const char* what) {
    std::string s = what;
    if (s.starts_with("[json.exception.")) {
        const size_t close = s.find("] ");
        if (close != std::string::npos) s = s.substr(close + 2);
    }
    if (s.starts_with("parse error")) {
        const size_t at = s.find(": ");
        if (at != std::string::npos) s = s.substr(at + 2);
    }
    for (const char* quoting : {"; last read: '", " parsing '"}) {
        const size_t at = s.find(quoting);
        if (at != std::string::npos) s.erase(at);
    }
    return s;
}

std::string key_path(const std::string& path, const char* key) {
    return path.empty() ? key : path + "." + key;
}

}  // namespace

Json parse(std::string_view text, int max_depth) {
    if (deeper_than(text, max_depth))
        throw JsonSyntaxError(0, "JSON nested more than " + std::to_string(max_depth) + " deep");
    Json doc;
    DomError error;
    try {
        if (parse_dom(text, doc, error)) return doc;
    } catch (const Json::exception& e) {
        throw JsonSyntaxError(0, "malformed JSON: " + reason(e.what()));
    }
    throw JsonSyntaxError(stop_line(text, error.byte), "malformed JSON at column " +
                                                           std::to_string(stop_column(text, error.byte)) + ": " +
                                                           reason(error.what.c_str()));
}

std::string describe(const Json& v) {
    switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array:
    case Json::value_t::binary: return "an array";  // a packed gid array (json_dom.hpp)
    case Json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    // Never quoted: the file can be any a map names, and a string in it
    // (a token in a JSON credentials file) is not the error's to show.
    case Json::value_t::string: return "a string";
    default:
        return "the number " + v.dump();  // never throws: no strings inside
    }
}

bool Node::has(const char* key) const {
    if (!value->is_object()) return false;
    const auto it = value->find(key);
    return it != value->end() && !it->is_null();
}

Node Node::operator[](const char* key) const {
    return {&value->at(key), key_path(path, key)};
}

Node Node::operator[](size_t index) const {
    return {&(*value)[index], path + "[" + std::to_string(index) + "]"};
}

void Node::fail(const std::string& problem) const {
    throw JsonError((path.empty() ? std::string("the document") : path) + " " + problem);
}

const Json& Node::object() const {
    if (!value->is_object()) fail("is " + describe(*value) + ", expected an object");
    return *value;
}

const Json& Node::array() const {
    // A "data" array read as a plain array after all (not as a layer's
    // cells): unpacked once, in the document the reader owns.
    if (is_packed_gids(*value)) unpack_gids(const_cast<Json&>(*value));
    if (!value->is_array()) fail("is " + describe(*value) + ", expected an array");
    return *value;
}

std::string Node::string() const {
    if (!value->is_string()) fail("is " + describe(*value) + ", expected a string");
    return value->get<std::string>();
}

double Node::number() const {
    if (!value->is_number()) fail("is " + describe(*value) + ", expected a number");
    const double d = value->get<double>();
    if (!std::isfinite(d)) fail("is " + describe(*value) + ", expected a finite number");
    return d;
}

bool Node::boolean() const {
    if (!value->is_boolean()) fail("is " + describe(*value) + ", expected true or false");
    return value->get<bool>();
}

int64_t Node::integer() const { return integer_as("an integer"); }

int64_t Node::integer_as(const char* what) const {
    if (value->is_number_unsigned()) {
        const uint64_t u = value->get<uint64_t>();
        if (u > static_cast<uint64_t>(INT64_MAX)) fail("is " + describe(*value) + ", too large");
        return static_cast<int64_t>(u);
    }
    if (value->is_number_integer()) return value->get<int64_t>();
    if (value->is_number_float()) {
        const double d = value->get<double>();
        // 2^62 keeps the cast exact and far from overflow.
        if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 0x1p62)
            return static_cast<int64_t>(d);
    }
    fail("is " + describe(*value) + ", expected " + what);
}

int64_t Node::integer_in(int64_t min, int64_t max, const char* what) const {
    const int64_t v = integer_as(what);
    if (v < min || v > max) fail("is " + describe(*value) + ", expected " + what);
    return v;
}

std::string string_or(const Node& n, const char* key, std::string_view fallback) {
    return n.has(key) ? n[key].string() : std::string(fallback);
}

double number_or(const Node& n, const char* key, double fallback) {
    return n.has(key) ? n[key].number() : fallback;
}

double extent_or(const Node& n, const char* key, double fallback) {
    const double v = number_or(n, key, fallback);
    if (v < 0) n[key].fail("is " + describe(*n[key].value) + ", expected a number of at least 0");
    return v;
}

bool bool_or(const Node& n, const char* key, bool fallback) {
    return n.has(key) ? n[key].boolean() : fallback;
}

namespace {

template <class T>
T field(const Node& n, const char* key, std::optional<T> fallback, int64_t min, int64_t max,
        const char* what) {
    if (!n.has(key)) {
        if (fallback) return *fallback;
        n.fail("has no \"" + std::string(key) + "\"");
    }
    return static_cast<T>(n[key].integer_in(min, max, what));
}

}  // namespace

int int_or(const Node& n, const char* key, std::optional<int> fallback) {
    return field<int>(n, key, fallback, INT_MIN, INT_MAX, "an integer");
}

int size_or(const Node& n, const char* key, std::optional<int> fallback) {
    return field<int>(n, key, fallback, 0, INT_MAX, "a non-negative integer");
}

uint32_t uint_or(const Node& n, const char* key, std::optional<uint32_t> fallback) {
    return field<uint32_t>(n, key, fallback, 0, UINT32_MAX, "a non-negative 32-bit integer");
}

const Json& array_or_empty(const Node& n, const char* key) {
    static const Json empty = Json::array();
    return n.has(key) ? n[key].array() : empty;
}

}  // namespace ds::json
