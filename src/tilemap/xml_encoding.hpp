// SPDX-License-Identifier: MIT
// An XML file's text as UTF-8, whatever encoding it declares: tinyxml2 reads
// UTF-8 only, and passes any other byte through into the strings it returns.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace ds::tmx {

// The text in UTF-8: transcoded (iconv) from the encoding of its XML
// declaration, or from UTF-16 when it starts with a UTF-16 byte-order mark;
// nullopt when it is UTF-8 already (checked, not copied: maps are mostly
// UTF-8 and may be 64 MiB). Throws EncodingError when the encoding is
// unknown or a byte is not valid in it (valid UTF-8 included), with the
// 1-based line of that byte.
std::optional<std::string> xml_text_as_utf8(std::string_view text);

class EncodingError : public std::exception {
public:
    EncodingError(int line, std::string message) : line_(line), message_(std::move(message)) {}
    int line() const { return line_; }
    const char* what() const noexcept override { return message_.c_str(); }

private:
    int line_;
    std::string message_;
};

}  // namespace ds::tmx
