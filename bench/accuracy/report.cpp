// SPDX-License-Identifier: MIT
#include <iterator>
#include "accuracy/report.hpp"

#include <cmath>

#include "accuracy/format.hpp"

namespace bench::accuracy {

namespace {

const int kWidths[] = {8, 2, 4, 9, 8, 5, 5, 8, 9, 14, 7, 7, 24, 8, 22, 8, 22};

void print_cells(std::FILE* out, const std::vector<std::string>& cs) {
    static_assert(std::size(kWidths) == 17, "a width per column of table_heads");
    for (size_t i = 0; i < cs.size(); ++i) std::fprintf(out, "%-*s ", kWidths[i], cs[i].c_str());
    std::fputc('\n', out);
}

template <class Pred>
std::string failing(const std::vector<Row>& rows, Pred bad) {
    std::string s;
    for (const Row& r : rows)
        if (bad(r)) s += (s.empty() ? "" : ", ") + config_name(r.cfg);
    return s;
}

Goal goal(std::string name, const std::string& bad, std::string ok_detail) {
    return {std::move(name), bad.empty(), bad.empty() ? std::move(ok_detail) : "not in: " + bad};
}

bool settled(const Run& r) { return r.repeat.period != 0 && r.repeat.held; }

}  // namespace

const Run& Row::deepest() const {
    const Run* best = &arena;
    for (const Run* r : {&drop, &stack, &crowd})
        if (r->worst.depth > best->worst.depth) best = r;
    return *best;
}

std::vector<Goal> judge(const std::vector<Row>& rows, const std::vector<Sinking>& sinking) {
    const auto swept = [](const Row& r) { return r.cfg.mode == ds::CollisionMode::Swept; };
    std::vector<Goal> goals;
    goals.push_back(goal("swept lets nothing through",
                         failing(rows, [&](const Row& r) { return swept(r) && (r.tunnel.escaped || r.tunnel.lodged); }),
                         "no projectile escaped or stuck, at any speed, in any swept row"));
    goals.push_back(goal("swept lets nothing through ramps",
                         failing(rows, [&](const Row& r) {
                             return swept(r) && (r.ramp_tunnel.escaped || r.ramp_tunnel.lodged);
                         }),
                         "no shot through or stuck in a ramp, at any speed, in any swept row"));
    goals.push_back(goal("resting contacts on: stack and crowd settle to period <= 2 and stay (both modes)",
                         failing(rows, [](const Row& r) { return r.cfg.resting && !(settled(r.stack) && settled(r.crowd)); }),
                         "every resting-contacts row"));
    goals.push_back(goal("resting contacts on: stack and crowd do not move at all",
                         failing(rows, [](const Row& r) {
                             return r.cfg.resting && (r.stack.max_dy || r.stack.max_dx || r.crowd.max_dy || r.crowd.max_dx);
                         }),
                         "dx = dy = 0 in every resting-contacts row"));
    goals.push_back(goal("trajectory error falls as 1/k (each ratio within 10% of 2)",
                         failing(rows, [](const Row& r) { return r.cfg.k > 1 && std::fabs(r.ratio - 2) > 0.2; }),
                         "every ratio"));
    std::string sunk;
    for (const Sinking& s : sinking)
        if (s.rule == ds::PushRule::Clipped && s.sunk != 0)
            sunk += (sunk.empty() ? "" : ", ") + s.scene + " " + std::to_string(s.n);
    goals.push_back({"default push rule: no body ends a frame 1 px or more inside a solid tile (issue 50)",
                     sunk.empty(), sunk.empty() ? "crowd, rain, bullets, platformer at every N" : "not in: " + sunk});
    return goals;
}

void print_header(std::FILE* out) { print_cells(out, table_heads()); }
void print_row(std::FILE* out, const Row& row) { print_cells(out, table_cells(row)); }

void print_goals(std::FILE* out, const std::vector<Goal>& goals) {
    for (const Goal& g : goals)
        std::fprintf(out, "goal %-7s %s (%s)\n", g.met ? "met:" : "MISSED:", g.name.c_str(), g.detail.c_str());
}

}  // namespace bench::accuracy
