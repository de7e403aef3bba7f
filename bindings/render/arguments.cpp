// SPDX-License-Identifier: MIT
#include "arguments.hpp"

#include <iterator>

#include "render/constants.hpp"

namespace ds::guile {

using namespace ds::render;

namespace {

SCM sym_world, sym_screen;

// kNamedColors' names as symbols, interned once (register_render_arguments).
SCM named_color_symbols[std::size(kNamedColors)];

// "white black … gray", for messages.
std::string color_names() {
    std::string names;
    for (const NamedColor& c : kNamedColors) (names += names.empty() ? "" : " ") += c.name;
    return names;
}

}  // namespace

bool color_arg(SCM v, Rgba& out, Failure& f, Arg what) {
    if (scm_is_symbol(v)) {
        for (size_t i = 0; i < std::size(kNamedColors); ++i)
            if (scm_is_eq(v, named_color_symbols[i])) {
                out = kNamedColors[i].rgba;
                return true;
            }
    }
    uint8_t c[4] = {0, 0, 0, 255};
    const long n = scm_ilength(v);
    bool ok = n == 3 || n == 4;
    SCM p = v;
    for (long i = 0; ok && i < n; ++i, p = SCM_CDR(p)) {
        ok = scm_is_unsigned_integer(SCM_CAR(p), 0, 255);
        if (ok) c[i] = static_cast<uint8_t>(scm_to_uint(SCM_CAR(p)));
    }
    if (!ok) {
        fail_arg(f, what, v, "(r g b) or (r g b a) of integers 0–255, or one of the names %s", color_names().c_str());
        return false;
    }
    out = {c[0], c[1], c[2], c[3]};
    return true;
}

bool space_arg(SCM v, Space& out, Failure& f) {
    if (scm_is_eq(v, sym_world)) out = Space::World;
    else if (scm_is_eq(v, sym_screen)) out = Space::Screen;
    else {
        fail_arg(f, "space", v, "world or screen");
        return false;
    }
    return true;
}

bool gid_arg(SCM v, const char* what, uint32_t& out, Failure& f) {
    return from_scm(v, out, what, f, "a gid (an exact integer ≥ 0, flip bits allowed)");
}

bool symbol_arg(SCM v, const char* what, std::string& out, Failure& f) {
    if (scm_is_symbol(v)) return from_scm(scm_symbol_to_string(v), out, what, f);
    fail_arg(f, what, v, "a symbol");
    return false;
}

SCM named_color_symbol(size_t i) { return named_color_symbols[i]; }

void register_render_arguments() {
    sym_world = scm_permanent_object(scm_from_utf8_symbol("world"));
    sym_screen = scm_permanent_object(scm_from_utf8_symbol("screen"));
    for (size_t i = 0; i < std::size(kNamedColors); ++i)
        named_color_symbols[i] = scm_permanent_object(
            scm_from_utf8_symboln(kNamedColors[i].name.data(), kNamedColors[i].name.size()));
}

}  // namespace ds::guile
