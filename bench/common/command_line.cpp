// SPDX-License-Identifier: MIT
#include "common/command_line.hpp"

#include <cstdio>
#include <stdexcept>

namespace bench {

namespace {

// Whether `parse` (std::stod, std::stoi, …) reads all of v, storing it in
// out; a throw reads nothing (so "" counts as read whole, out left as it was).
template <class T, class Parse>
bool parse_whole(const std::string& v, T& out, Parse parse) {
    size_t used = 0;
    try {
        out = parse(v, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    return used == v.size();
}

std::string quoted(const std::string& arg) {
    if (!arg.empty() && arg.find_first_of(" \t'\"$\\") == std::string::npos) return arg;
    std::string q = "'";
    for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

int count_arg(const std::string& opt, const std::string& v, int least) {
    int n = 0;
    const bool whole = parse_whole(v, n, [](const std::string& s, size_t* used) { return std::stoi(s, used); });
    if (!whole || n < least) throw std::invalid_argument(opt + ": expected a count, got '" + v + "'");
    return n;
}

bool rounds_and_org(int argc, char** argv, const char* mode, int& rounds, std::string& org) {
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--rounds" && i + 1 < argc) rounds = count_arg(a, argv[++i], 1);
        else if (a == "--org" && i + 1 < argc) org = argv[++i];
        else {
            std::fprintf(stderr, "usage: downstroke-bench %s [--rounds R] [--org FILE]\n", mode);
            return false;
        }
    }
    return true;
}

std::string command_line(int argc, char** argv) {
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + quoted(argv[i]);
    return command;
}

double positive_arg(const std::string& opt, const std::string& v) {
    double d = 0;
    const bool whole = parse_whole(v, d, [](const std::string& s, size_t* used) { return std::stod(s, used); });
    if (!whole || !(d > 0)) throw std::invalid_argument(opt + ": expected a positive number, got '" + v + "'");
    return d;
}

}  // namespace bench
