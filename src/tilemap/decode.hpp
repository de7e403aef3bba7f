// SPDX-License-Identifier: MIT
// Turning the text of a TMX <data> or <chunk> element into gids: base64,
// the three compressions Tiled writes, and CSV. Knows nothing of XML or of
// file names: failures throw DecodeError and the loader adds where they came from.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace ds::tmx {

class DecodeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class Compression : uint8_t { None, Zlib, Gzip, Zstd };

// Standard base64; whitespace anywhere is skipped, padding is optional.
std::vector<uint8_t> decode_base64(std::string_view text);

// The whole compressed stream, refusing to produce more than max_bytes: the
// caller knows how many cells to expect, and a forged stream must not be
// able to exhaust memory.
std::vector<uint8_t> decompress(Compression c, std::span<const uint8_t> data, size_t max_bytes);

// Little-endian uint32 gids; the byte count must be a multiple of 4.
std::vector<uint32_t> gids_from_bytes(std::span<const uint8_t> bytes);

// Comma-separated decimal gids, whitespace around each ignored; one trailing
// comma is allowed (Tiled ends every row but the last with one).
std::vector<uint32_t> parse_csv(std::string_view text);
// The same, stopping after max_values: the caller knows how many cells to
// expect, and one more already tells that the data is too long.
std::vector<uint32_t> parse_csv(std::string_view text, size_t max_values);

}  // namespace ds::tmx
