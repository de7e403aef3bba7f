// SPDX-License-Identifier: MIT
// Strict, typed access to a parsed JSON document (nlohmann::json) for the
// Tiled JSON readers: every value is fetched by key with the type it must
// have, and a missing or mistyped one is a JsonError whose message names
// the JSON path (`layers[2].chunks[0].width`), what is there and what was
// expected. Knows no file names: the reader adds the file.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ds::json {

using Json = nlohmann::json;

class JsonError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Malformed JSON: `line` (1-based) is where the parser stopped.
class JsonSyntaxError : public std::runtime_error {
public:
    JsonSyntaxError(int line, const std::string& message)
        : std::runtime_error(message), line(line) {}
    int line;
};

// The whole text as one JSON value. Refuses (JsonSyntaxError) malformed
// JSON, ill-formed UTF-8, and arrays/objects nested deeper than max_depth,
// checked before parsing so that no recursion grows with the input.
Json parse(std::string_view text, int max_depth);

// A value in the document and the path that leads to it ("" at the root).
struct Node {
    const Json* value;
    std::string path;

    bool has(const char* key) const;  // an object with that key (null counts as absent)
    Node operator[](const char* key) const;  // has(key) must hold
    Node operator[](size_t index) const;

    // This node as a type; a JsonError when it is not.
    const Json& object() const;
    const Json& array() const;
    std::string string() const;
    double number() const;  // finite
    bool boolean() const;
    int64_t integer() const;  // an integral number (1 and 1.0 alike)
    int64_t integer_as(const char* what) const;  // the same, `what` naming it in the message
    // An integer in [min, max]; `what` names the range in the message.
    int64_t integer_in(int64_t min, int64_t max, const char* what) const;

    [[noreturn]] void fail(const std::string& problem) const;  // "<path> <problem>"
};

// What a value is, for messages: "a string (\"4\")", "an array", "null".
std::string describe(const Json& v);

// Fields of an object node: the fallback when the key is absent, else the
// value with the type asked for.
std::string string_or(const Node& n, const char* key, std::string_view fallback = "");
double number_or(const Node& n, const char* key, double fallback);
double extent_or(const Node& n, const char* key, double fallback);  // a number ≥ 0: an object's width, height
bool bool_or(const Node& n, const char* key, bool fallback);
int int_or(const Node& n, const char* key, std::optional<int> fallback);  // any int
int size_or(const Node& n, const char* key, std::optional<int> fallback);  // 0 … INT_MAX
uint32_t uint_or(const Node& n, const char* key, std::optional<uint32_t> fallback);  // 0 … 2^32−1
// The array at `key`, or an empty one when absent.
const Json& array_or_empty(const Node& n, const char* key);

}  // namespace ds::json
