// SPDX-License-Identifier: MIT
#include "accuracy/format.hpp"

#include <cmath>
#include <cstdio>

namespace bench::accuracy {

namespace {

std::string percent(long part, long whole) {
    char buf[32];
    const double share = whole ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
    std::snprintf(buf, sizeof buf, "%.2f%%", share);
    return buf;
}

std::string ratio(const Row& r) { return r.cfg.k == 1 ? "-" : sig3(r.ratio); }

std::string landing(const Trajectory& t) {
    if (t.land_frame < 0) return "never";
    return (t.land_error() > 0 ? "+" : "") + std::to_string(t.land_error());
}

std::string safe_to(const Tunneling& t) {
    return std::to_string(t.safe_to()) + (t.first_escape == 0 ? " (all)" : "");
}

}  // namespace

std::string px(double v) {
    if (v == std::floor(v) && std::fabs(v) < 1e9) return std::to_string(static_cast<long>(v));
    return sig3(v);
}

std::string share(double fraction) { return sig3(100 * fraction) + "%"; }

std::string repeat(const Repeat& r) {
    if (r.period == 0) return "none";
    std::string s = "p" + std::to_string(r.period) + " from " + std::to_string(r.from);
    return s + (r.held ? ", held" : ", broke " + std::to_string(r.broke_at));
}

std::string where(const Run& run) {
    if (run.worst.depth == 0) return "-";
    return run.scene + (run.worst.in_tile ? " tile " : " immovable ") + run.worst.cause;
}

std::string config_name(const Config& c) {
    return std::string(c.mode_name()) + " k=" + std::to_string(c.k) + " rest " + (c.resting ? "on" : "off");
}

const std::vector<std::string>& table_heads() {
    static const std::vector<std::string> heads = {
        "mode", "k", "rest", "ms/frame", "traj px", "ratio", "land", "escaped", "safe to", "ramps: escaped", "lodged",
        "pen px", "deepest in", "stack dy", "stack repeat", "crowd dy", "crowd repeat"};
    return heads;
}

std::vector<std::string> table_cells(const Row& r) {
    return {r.cfg.mode_name(), std::to_string(r.cfg.k), r.cfg.resting ? "on" : "off", sig3(r.arena.median_ms),
            px(r.traj.max_error), ratio(r), landing(r.traj), percent(r.tunnel.escaped, r.tunnel.tested),
            safe_to(r.tunnel), percent(r.ramp_tunnel.escaped, r.ramp_tunnel.tested),
            percent(r.ramp_tunnel.lodged, r.ramp_tunnel.tested), px(r.deepest().worst.depth), where(r.deepest()), px(r.stack.max_dy),
            repeat(r.stack.repeat), px(r.crowd.max_dy), repeat(r.crowd.repeat)};
}

}  // namespace bench::accuracy
