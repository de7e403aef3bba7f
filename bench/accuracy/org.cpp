// SPDX-License-Identifier: MIT
// The Org document of `downstroke-bench accuracy` (accuracy/report.hpp): the
// run's figures and tables between the BEGIN and END markers. How each
// figure is measured is hand-written in docs/accuracy.org, outside them.
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "accuracy/format.hpp"
#include "accuracy/notes.hpp"
#include "accuracy/report.hpp"
#include "common/org_file.hpp"

namespace bench::accuracy {

namespace {

const char* kBegin = "# BEGIN downstroke-bench accuracy";
const char* kEnd = "# END downstroke-bench accuracy";

// Only for a file without the markers: what each figure means is written by
// hand in docs/accuracy.org, around its generated part.
const char* kIntro =
    "#+title: Accuracy\n\n"
    "The figures of =downstroke-bench accuracy=; how each is measured is told in\n"
    "=docs/accuracy.org=, outside its generated part.\n\n";

std::string cell(std::string s) {
    for (char& c : s)
        if (c == '|') c = '/';
    return s;
}

std::string org_row(const std::vector<std::string>& cells) {
    std::string s = "|";
    for (const std::string& c : cells) s += " " + cell(c) + " |";
    return s + "\n";
}

std::vector<std::string> config_cells(const Config& c) {
    return {c.mode_name(), std::to_string(c.k), c.resting ? "on" : "off"};
}

// What the run covered: the frame counts and sizes docs/accuracy.org gives
// for the full run, as this run used them.
std::string plan(const Plan& p) {
    std::ostringstream o;
    o << "| trajectory   | " << p.traj_frames << " frames |\n"
      << "| tunneling    | 1 … " << p.max_speed << " px/frame, "
      << (static_cast<long>(p.max_speed) * (p.max_speed + 1) / 2) << " shots; against ramps "
      << (static_cast<long>(p.max_speed) * (p.max_speed + 1) * 4) << " |\n"
      << "| arena, drop  | " << p.scene_frames << " frames; arena " << p.arena_n << " boxes |\n"
      << "| stack, crowd | " << p.drift_frames << " frames; stack " << p.stack_n << " boxes, crowd N = " << p.crowd_n
      << " |\n"
      << "| long runs    | "
      << (p.shortcut ? "stopped once the whole state cycles" : "every frame stepped (=--every-frame=)") << " |\n"
      << "| threads      | " << p.jobs << " for the untimed runs |\n\n";
    return o.str();
}

std::string machine(const RunInfo& i) {
    std::ostringstream o;
    o << "| machine    | " << cell(i.cpu) << ", " << i.cores << " cores, Linux " << i.kernel << " |\n"
      << "| date       | " << i.date << " |\n"
      << "| build type | " << (i.build_type.empty() ? "(none)" : i.build_type) << ", =" << i.core_flags << "= |\n"
      << "| compiler   | " << i.compiler << " |\n"
      << "| source     | " << cell(i.source) << " |\n"
      << "| command    | =" << cell(i.command) << "= |\n"
      << "| whole run  | " << sig3(i.total_s) << " s |\n\n";
    return o.str();
}

std::string main_table(const std::vector<Row>& rows) {
    std::string s = org_row(table_heads());
    bool first = true;
    for (const Row& r : rows) {
        if (r.cfg.k == 1 && !first) s += "|-\n";
        if (first) s += "|-\n";
        first = false;
        s += org_row(table_cells(r));
    }
    return s + "\n";
}

std::string depth(const Run& r) {
    if (r.worst.depth == 0) return "0";
    return px(r.worst.depth) + " (" + (r.worst.in_tile ? "tile" : "immovable") + ", " + r.worst.cause + ", frame " +
           std::to_string(r.worst.frame) + "; " + share(r.inside_share()) + ")";
}

template <class Cell>
std::string scene_table(const std::vector<Row>& rows, Cell cellf) {
    std::string s = org_row({"mode", "k", "rest", "arena", "drop", "stack", "crowd"}) + "|-\n";
    for (const Row& r : rows) {
        std::vector<std::string> cs = config_cells(r.cfg);
        for (const Run* run : {&r.arena, &r.drop, &r.stack, &r.crowd}) cs.push_back(cellf(*run));
        s += org_row(cs);
    }
    return s + "\n";
}

// Issue 50's check: per scene and N, the default push rule beside the seed's.
std::string sinking_table(const std::vector<Sinking>& all, long frames) {
    auto of = [](const Sinking& s) {
        return std::vector<std::string>{std::to_string(s.sunk), std::to_string(s.sunk_at_end),
                                        s.deepest == 0 ? "0" : px(s.deepest)};
    };
    std::string t = org_row({"scene", "N", "clipped: sunk", "at end", "deepest px", "seed: sunk", "at end",
                             "deepest px"}) + "|-\n";
    for (size_t i = 0; i + 1 < all.size(); i += 2) {
        const Sinking& c = all[i].rule == ds::PushRule::Clipped ? all[i] : all[i + 1];
        const Sinking& seed = all[i].rule == ds::PushRule::Clipped ? all[i + 1] : all[i];
        std::vector<std::string> cs{c.scene, std::to_string(c.n)};
        for (const auto& v : of(c)) cs.push_back(v);
        for (const auto& v : of(seed)) cs.push_back(v);
        t += org_row(cs);
    }
    return t + "\nsunk: the bodies that ended a frame " + px(kSunkDepth) + " px or more inside a solid tile, at any of " +
           std::to_string(frames) + " frames (the speed benchmark's scenes and stepping: swept, k = 1, no resting " +
           "contacts); at end: at the last frame's end; deepest: the smaller axis overlap with one cell.\n\n";
}

std::string goals(const std::vector<Goal>& gs) {
    std::string s;
    for (const Goal& g : gs) s += "- " + std::string(g.met ? "met" : "*MISSED*") + " :: " + g.name + " (" + g.detail + ")\n";
    return s + "\n";
}

std::string plot(const Document& d) {
    if (d.png_link.empty()) return "The plot was not drawn (" + d.plot_note + ").\n\n";
    return "[[file:" + d.png_link + "]]\n\n";
}

std::string results(const Document& d) {
    std::ostringstream o;
    o << "* Latest results\n\n" << machine(d.info) << plan(d.plan);
    if (d.plan.quick) o << "This is a =--quick= run: fewer frames than the full benchmark.\n\n";
    o << main_table(d.rows) << "** Goals\n\n" << goals(d.goals) << "** Plot\n\n" << plot(d)
      << "** Penetration by scene\n\n" << scene_table(d.rows, depth) << penetration_summary(d.rows)
      << "** Sinking at every N\n\n" << sinking_table(d.sinking, d.plan.sinking_frames)
      << "** Drift sideways\n\n" << scene_table(d.rows, [](const Run& r) { return px(r.max_dx); })
      << "** Time per frame by scene\n\n" << scene_table(d.rows, [](const Run& r) { return sig3(r.median_ms); });
    return o.str();
}

}  // namespace

void write_org(const std::string& file, const Document& doc) {
    const std::string generated = std::string(kBegin) +
                                  " (generated by downstroke-bench accuracy; edits here are overwritten)\n" +
                                  results(doc) + kEnd + "\n";
    write_generated(file, kBegin, kEnd, generated, kIntro);
}

}  // namespace bench::accuracy
