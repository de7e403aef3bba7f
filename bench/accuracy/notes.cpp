// SPDX-License-Identifier: MIT
#include "accuracy/notes.hpp"

#include <map>
#include <sstream>

#include "accuracy/format.hpp"

namespace bench::accuracy {

namespace {

struct Tally {
    int runs = 0, inside = 0, immovable = 0;
    std::map<std::string, int> causes;  // of each run's deepest case
    const Run* deepest = nullptr;
    const Config* deepest_cfg = nullptr;
};

Tally tally(const std::vector<Row>& rows) {
    Tally t;
    for (const Row& r : rows)
        for (const Run* run : {&r.arena, &r.drop, &r.stack, &r.crowd}) {
            ++t.runs;
            if (run->worst.depth == 0) continue;
            ++t.inside;
            ++t.causes[run->worst.cause];
            if (!run->worst.in_tile) ++t.immovable;
            if (!t.deepest || run->worst.depth > t.deepest->worst.depth) t.deepest = run, t.deepest_cfg = &r.cfg;
        }
    return t;
}

}  // namespace

std::string penetration_summary(const std::vector<Row>& rows) {
    const Tally t = tally(rows);
    std::ostringstream o;
    if (t.inside == 0) {
        o << "No body ended a frame inside a solid tile or an immovable body in any run.\n\n";
        return o.str();
    }
    o << "Bodies ended frames inside a solid in " << t.inside << " of " << t.runs
      << " scene runs; the deepest, " << px(t.deepest->worst.depth) << " px, in " << t.deepest->scene << " ("
      << config_name(*t.deepest_cfg) << ", frame " << t.deepest->worst.frame << ")"
      << (t.deepest->worst.depth >= 8
              ? std::string(", is an 8×8 box wholly inside ") + (t.deepest->worst.in_tile ? "a tile" : "an immovable body")
              : "")
      << ". "
      << (t.immovable == 0            ? "Every one of those deepest cases is inside a tile, none inside an immovable body."
          : t.immovable == t.inside ? "Every one of those deepest cases is inside an immovable body, none inside a tile."
                                      : std::to_string(t.immovable) +
                                            " of those deepest cases are inside an immovable body, the rest in tiles.")
      << " By the cause of each run's deepest case:";
    for (const auto& [cause, n] : t.causes) o << " " << cause << " " << n << ";";
    o.seekp(-1, std::ios_base::cur);
    o << ".\n\n";
    return o.str();
}

}  // namespace bench::accuracy
