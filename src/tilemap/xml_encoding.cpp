// SPDX-License-Identifier: MIT
#include "xml_encoding.hpp"

#include <iconv.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>

#include "utf8.hpp"

namespace ds::tmx {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string byte_text(unsigned char b) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", b);
    return buf;
}

// The encoding= of a leading <?xml …?> declaration, or "" when none.
std::string declared_encoding(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    if (!text.starts_with("<?xml")) return "";
    // Only a declaration that closes, so that an unclosed one never reads
    // an encoding= further on (a layer's <data encoding="csv">).
    const size_t close = text.find("?>");
    if (close == std::string_view::npos) return "";
    const std::string_view decl = text.substr(0, std::min(close, text.find('<', 1)));
    const size_t at = decl.find("encoding");
    if (at == std::string_view::npos) return "";
    size_t q = decl.find_first_of("\"'", at);
    if (q == std::string_view::npos) return "";
    const size_t end = decl.find(decl[q], q + 1);
    if (end == std::string_view::npos) return "";
    return std::string(decl.substr(q + 1, end - q - 1));
}

bool is_utf8_name(const std::string& name) {
    const std::string n = lower(name);
    return n.empty() || n == "utf-8" || n == "utf8";
}

// Closes the descriptor however the conversion ends.
struct Iconv {
    iconv_t cd;
    ~Iconv() { iconv_close(cd); }
};

std::string transcode(std::string_view text, const std::string& from) {
    Iconv conv{iconv_open("UTF-8", from.c_str())};
    if (conv.cd == reinterpret_cast<iconv_t>(-1))
        throw EncodingError(1, "unknown encoding '" + from + "' in the XML declaration");
    std::string out;
    char* in = const_cast<char*>(text.data());
    size_t in_left = text.size();
    char buf[4096];
    while (in_left > 0) {
        char* o = buf;
        size_t o_left = sizeof buf;
        const size_t r = iconv(conv.cd, &in, &in_left, &o, &o_left);
        out.append(buf, static_cast<size_t>(o - buf));
        if (r != static_cast<size_t>(-1) || errno == E2BIG) continue;
        // EILSEQ, or EINVAL for a sequence cut off by the end of the file.
        const std::string what = in_left > 0 ? "byte " + byte_text(static_cast<unsigned char>(*in))
                                             : "the end of the file";
        throw EncodingError(line_at(out, out.size()),
                            what + " is not valid " + from + " text");
    }
    return out;
}

// Refuses the first byte of `utf8` that is not valid UTF-8.
void check_utf8(std::string_view utf8) {
    if (const size_t bad = first_invalid_utf8(utf8); bad != std::string_view::npos)
        throw EncodingError(line_at(utf8, bad), "byte " + byte_text(static_cast<unsigned char>(utf8[bad])) +
                                                    " is not valid UTF-8");
}

}  // namespace

std::optional<std::string> xml_text_as_utf8(std::string_view text) {
    std::string from;
    if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF"))
        from = "UTF-16";  // iconv reads the mark and drops it
    else
        from = declared_encoding(text);
    // A UTF-16 file's declaration names UTF-16 but cannot be read as bytes.
    if (!from.empty() && lower(from).starts_with("utf-16") && !text.starts_with("\xFF\xFE") &&
        !text.starts_with("\xFE\xFF"))
        throw EncodingError(1, "the XML declaration names " + from +
                                   " but the file has no UTF-16 byte-order mark");
    if (is_utf8_name(from)) {
        check_utf8(text);
        return std::nullopt;
    }
    std::string utf8 = transcode(text, from);
    check_utf8(utf8);
    return utf8;
}

}  // namespace ds::tmx
