// SPDX-License-Identifier: MIT
// Parsing a JSON document into nlohmann's DOM, except that the gid arrays
// of tile layers and chunks ("data": [1, 2, …], every element a whole
// number up to 2^32 − 1) are kept packed, four bytes a gid, in a binary
// value instead of one JSON value per cell: building and destroying a
// million of those cost a 1000 × 1000 map more than its parsing.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::json {

// Why parse_dom stopped: the byte it stopped at and nlohmann's message.
struct DomError {
    size_t byte = 0;
    std::string what;
};

// Fills `out` with the document; false with `error` set when it is not JSON.
bool parse_dom(std::string_view text, nlohmann::json& out, DomError& error);

// Whether v is a packed gid array, and its gids.
bool is_packed_gids(const nlohmann::json& v);
std::vector<uint32_t> packed_gids(const nlohmann::json& v, size_t max);

// A packed gid array turned back into an ordinary array, in place.
void unpack_gids(nlohmann::json& v);

}  // namespace ds::json
