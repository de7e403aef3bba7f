// SPDX-License-Identifier: MIT
// Whether text is valid UTF-8, and where it stops being: every string the
// map model holds and every message the loader writes must be, so that the
// Scheme side never meets a byte it cannot decode.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace ds::tmx {

// The offset of the first byte that does not begin or continue a valid
// UTF-8 sequence (overlong forms, surrogates and code points past U+10FFFF
// are invalid), or npos when the whole text is valid.
size_t first_invalid_utf8(std::string_view text);

// At most `max_bytes` of valid UTF-8 `text`, cut before a whole character,
// with "…" after it when anything was cut: a value quoted in a message.
std::string quoted_prefix(std::string_view text, size_t max_bytes);

// The 1-based line of `offset` in `text`.
int line_at(std::string_view text, size_t offset);

}  // namespace ds::tmx
