// SPDX-License-Identifier: MIT
#include "decode.hpp"

#include <zlib.h>
#include <zstd.h>

#include <charconv>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace ds::tmx {

namespace {

constexpr size_t kChunk = 16384;

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

// A character quoted for a message: control and non-ASCII bytes as \xNN so
// the message stays one readable line.
std::string quoted_char(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", u);
    return buf;
}

void append_checked(std::vector<uint8_t>& out, const uint8_t* data, size_t n, size_t max_bytes,
                    const char* what) {
    if (out.size() + n > max_bytes)
        throw DecodeError(std::string("decompressed ") + what + " data is larger than the " +
                          std::to_string(max_bytes) + " bytes the layer size allows");
    out.insert(out.end(), data, data + n);
}

// zlib and gzip both: windowBits 15+32 detects the header.
std::vector<uint8_t> inflate_any(std::span<const uint8_t> data, size_t max_bytes,
                                 const char* what) {
    if (data.size() > UINT_MAX) throw DecodeError(std::string(what) + " data is too large");
    z_stream zs{};
    if (inflateInit2(&zs, 15 + 32) != Z_OK) throw DecodeError("cannot initialise zlib");
    std::unique_ptr<z_stream, int (*)(z_stream*)> guard(&zs, inflateEnd);
    zs.next_in = const_cast<Bytef*>(data.data());  // zlib's API is not const-correct
    zs.avail_in = static_cast<uInt>(data.size());
    std::vector<uint8_t> out;
    uint8_t buf[kChunk];
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
        zs.next_out = buf;
        zs.avail_out = sizeof buf;
        rc = inflate(&zs, Z_NO_FLUSH);
        const size_t produced = sizeof buf - zs.avail_out;
        if (rc == Z_NEED_DICT || rc == Z_DATA_ERROR || rc == Z_MEM_ERROR || rc == Z_STREAM_ERROR)
            throw DecodeError(std::string("corrupt ") + what + " data" +
                              (zs.msg ? std::string(": ") + zs.msg : std::string()));
        // Output space was available, so no progress means the input ran out.
        if (rc == Z_BUF_ERROR && produced == 0)
            throw DecodeError(std::string("corrupt ") + what + " data: truncated stream");
        append_checked(out, buf, produced, max_bytes, what);
    }
    return out;
}

std::vector<uint8_t> unzstd(std::span<const uint8_t> data, size_t max_bytes) {
    if (data.empty()) throw DecodeError("corrupt zstd data: empty stream");
    std::unique_ptr<ZSTD_DStream, size_t (*)(ZSTD_DStream*)> ds(ZSTD_createDStream(),
                                                                ZSTD_freeDStream);
    if (!ds) throw DecodeError("cannot initialise zstd");
    ZSTD_initDStream(ds.get());
    // Streaming serves frames with and without a recorded content size, and
    // several concatenated frames, through one path.
    ZSTD_inBuffer in{data.data(), data.size(), 0};
    std::vector<uint8_t> out;
    uint8_t buf[kChunk];
    for (;;) {
        ZSTD_outBuffer o{buf, sizeof buf, 0};
        const size_t ret = ZSTD_decompressStream(ds.get(), &o, &in);
        if (ZSTD_isError(ret))
            throw DecodeError(std::string("corrupt zstd data: ") + ZSTD_getErrorName(ret));
        append_checked(out, buf, o.pos, max_bytes, "zstd");
        if (in.pos == in.size) {
            if (ret == 0) break;  // the last frame is complete and flushed
            // Room left in the output yet the frame is unfinished: input ran out.
            if (o.pos < o.size) throw DecodeError("corrupt zstd data: truncated stream");
        }
    }
    return out;
}

}  // namespace

std::vector<uint8_t> decode_base64(std::string_view text) {
    std::vector<uint8_t> out;
    out.reserve(text.size() / 4 * 3 + 3);
    uint32_t acc = 0;
    int bits = 0;
    size_t chars = 0, padding = 0;
    for (const char c : text) {
        if (is_space(c)) continue;
        if (c == '=') {
            ++padding;
            continue;
        }
        if (padding > 0) throw DecodeError("invalid base64: data after '=' padding");
        const int v = base64_value(c);
        if (v < 0) throw DecodeError("invalid base64 character " + quoted_char(c));
        acc = (acc << 6) | static_cast<uint32_t>(v);
        bits += 6;
        ++chars;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<uint8_t>(acc >> bits));
            acc &= (1u << bits) - 1;
        }
    }
    // One character of a group encodes less than a byte: the text was cut.
    if (chars % 4 == 1 || (padding > 0 && (padding > 2 || (chars + padding) % 4 != 0)))
        throw DecodeError("truncated base64 data (" + std::to_string(chars + padding) +
                          " characters)");
    return out;
}

std::vector<uint8_t> decompress(Compression c, std::span<const uint8_t> data, size_t max_bytes) {
    switch (c) {
        case Compression::None:
            if (data.size() > max_bytes)
                throw DecodeError("layer data is larger than the " + std::to_string(max_bytes) +
                                  " bytes the layer size allows");
            return {data.begin(), data.end()};
        case Compression::Zlib:
            return inflate_any(data, max_bytes, "zlib");
        case Compression::Gzip:
            return inflate_any(data, max_bytes, "gzip");
        case Compression::Zstd:
            return unzstd(data, max_bytes);
    }
    throw DecodeError("unknown compression");
}

std::vector<uint32_t> gids_from_bytes(std::span<const uint8_t> bytes) {
    if (bytes.size() % 4 != 0)
        throw DecodeError("layer data is " + std::to_string(bytes.size()) +
                          " bytes, not a whole number of 4-byte gids");
    std::vector<uint32_t> gids(bytes.size() / 4);
    for (size_t i = 0; i < gids.size(); ++i) {
        const uint8_t* b = &bytes[i * 4];
        gids[i] =
            uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
    }
    return gids;
}

std::vector<uint32_t> parse_csv(std::string_view text) { return parse_csv(text, SIZE_MAX); }

std::vector<uint32_t> parse_csv(std::string_view text, size_t max_values) {
    std::vector<uint32_t> gids;
    size_t pos = 0;
    while (pos <= text.size() && gids.size() < max_values) {
        size_t comma = text.find(',', pos);
        if (comma == std::string_view::npos) comma = text.size();
        std::string_view tok = text.substr(pos, comma - pos);
        while (!tok.empty() && is_space(tok.front())) tok.remove_prefix(1);
        while (!tok.empty() && is_space(tok.back())) tok.remove_suffix(1);
        const bool last = comma == text.size();
        // Nothing after the final comma (or no data at all) is not a cell.
        if (tok.empty() && last) break;
        uint32_t v = 0;
        const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
        if (tok.empty() || ec != std::errc() || end != tok.data() + tok.size())
            throw DecodeError("invalid CSV value '" + std::string(tok.substr(0, 40)) + "'");
        gids.push_back(v);
        pos = comma + 1;
    }
    return gids;
}

}  // namespace ds::tmx
