// SPDX-License-Identifier: MIT
#include "common/org_file.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bench {

void write_generated(const std::string& file, const std::string& begin_marker, const std::string& end_marker,
                     const std::string& generated, const std::string& fresh_before,
                     const std::string& fresh_after) {
    std::string before = fresh_before, after = fresh_after;
    if (std::ifstream in(file); in) {
        std::stringstream ss;
        ss << in.rdbuf();
        const std::string old = ss.str();
        const auto b = old.find(begin_marker), e = old.find(end_marker);
        if (b != std::string::npos && e != std::string::npos && e > b) {
            before = old.substr(0, b);
            const auto eol = old.find('\n', e);
            after = eol == std::string::npos ? "" : old.substr(eol + 1);
        } else if (!old.empty()) {
            // A file without this section keeps everything it holds: the
            // section goes at its end (other benches write the same file).
            before = old + (old.back() == '\n' ? "\n" : "\n\n");
            after.clear();
        }
    }
    std::ofstream o(file);
    o << before << generated << after;
    if (!o) throw std::runtime_error("cannot write " + file);
}

std::string sig3(double v) {
    char buf[64];
    const double a = std::fabs(v);
    int decimals = a == 0 ? 0 : 2 - static_cast<int>(std::floor(std::log10(a)));
    decimals = decimals < 0 ? 0 : decimals > 6 ? 6 : decimals;
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

}  // namespace bench
