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

const char* kPushed =
    "/pushed/ — the cause the seed's order gives: a frame resolves tiles\n"
    "before entity push-apart (the per-entity steps, tile collisions among\n"
    "them, then =resolve-entity-collisions=), and push-apart moves bodies\n"
    "without looking at tiles. A box landing fast on one that stands on the\n"
    "floor overlaps it deeply, and the even split of that overlap shoves the\n"
    "lower box down into the floor (a sideways split shoves a box into a\n"
    "wall); the pairs are resolved one after another in one pass, so the\n"
    "pushes through a column of boxes landing together can add up in the\n"
    "bottom one. Nothing looks at the tiles again until the next (sub-)frame's\n"
    "tile steps, which look only along an axis the body moves on. Sub-frames\n"
    "shrink each landing's overlap (a sub-frame's move is v/k) and with it\n"
    "each push. Resting contacts make a box at rest hold a lander up as an\n"
    "immovable body would, but only once it is at rest — still, exactly on a\n"
    "tile or on a still box — so a crowd landing all at once still pushes.\n\n";

const char* kCarried =
    "/carried/ — the body began the frame already inside a solid, put there\n"
    "by the previous frame's push-apart, and its own tile steps did not get\n"
    "it out, or moved it somewhere worse. The seed's tile steps assume a box\n"
    "starts outside every solid: the x step treats every solid cell the box\n"
    "overlaps in the rows it spans as a wall ahead — the floor it has sunk\n"
    "into included — and puts the box back beside that cell's column, on the\n"
    "side it came from: next to a wall, inside the wall. The y step then does\n"
    "the same along y.\n\n";

const char* kAlone =
    "/alone/ — the body began the frame outside every solid and its own tile\n"
    "steps left it inside one: a failure of tile collision itself, not of the\n"
    "order of the steps.\n\n";

}  // namespace

std::string penetration_notes(const std::vector<Row>& rows) {
    const Tally t = tally(rows);
    std::ostringstream o;
    if (t.inside == 0) {
        o << "No body ended a frame inside a solid tile or an immovable body in any run.\n\n";
        return o.str();
    }
    o << "Bodies ended frames inside a solid in " << t.inside << " of " << t.runs
      << " scene runs; the deepest, " << px(t.deepest->worst.depth) << " px, in " << t.deepest->scene << " ("
      << config_name(*t.deepest_cfg) << ", frame " << t.deepest->worst.frame << ")"
      << (t.deepest->worst.depth >= 8 ? ", is an 8×8 box wholly inside a tile" : "") << ". "
      << (t.immovable ? std::to_string(t.immovable) + " of those deepest cases are inside an immovable body, the rest in tiles."
                      : "Every one of those deepest cases is inside a tile, none inside an immovable body.")
      << " By the cause of each run's deepest case:";
    for (const auto& [cause, n] : t.causes) o << " " << cause << " " << n << ";";
    o.seekp(-1, std::ios_base::cur);
    o << ".\n\n";
    if (t.causes.count("pushed")) o << kPushed;
    if (t.causes.count("carried")) o << kCarried;
    if (t.causes.count("alone")) o << kAlone;
    return o.str();
}

}  // namespace bench::accuracy
