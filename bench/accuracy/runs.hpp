// SPDX-License-Identifier: MIT
// Long runs of one scene under one Config, watched frame by frame: how deep
// any body ends a frame inside a solid, how far bodies drift from where they
// started, whether the frame-end positions fall into an exact repeat, and
// how long a frame takes.
#pragma once
#include <string>

#include "accuracy/measures.hpp"

namespace bench::accuracy {

// The deepest a body ended a frame inside a solid tile or an immovable
// body: the smaller of the two axis overlaps with that cell or body.
struct Depth {
    double depth = 0;  // px; 0: never inside anything
    long frame = -1;
    long body = -1;
    bool in_tile = true;  // else inside an immovable body
    // The frame replayed from its start with only this body and the
    // immovables: "pushed" when the body then ends outside (other bodies
    // pushed it in); else "carried" when it started the frame inside a solid
    // already (its own steps did not get it out), "alone" when it did not
    // (its own steps put it in).
    std::string cause;
};

// The frame-end positions repeat with `period` (1 or 2) frames from frame
// `from` on, checked for at least `min_run` frames; `held`: until the end.
struct Repeat {
    int period = 0;  // 0: no repeat of period ≤ 2 ever lasted min_run frames
    long from = -1;
    bool held = false;
    long broke_at = -1;  // when it did not hold: the first frame that broke it
};

struct Run {
    std::string scene;
    long frames = 0;   // the frames the figures cover
    long stepped = 0;  // the frames actually run (fewer after a shortcut)
    long movers = 0;   // bodies that are not immovable
    long inside = 0;   // body-frames that ended inside a solid
    // The share of the movers' frame ends that were inside a solid.
    double inside_share() const { return movers && frames ? static_cast<double>(inside) / (movers * frames) : 0; }
    double median_ms = 0;  // Frame::step wall time per frame
    Depth worst;
    double max_dy = 0, max_dx = 0;  // px, largest |Δ| from the start position (movers)
    Repeat repeat;
};

// With `shortcut`, the run stops early once the whole state of every body
// (every field Frame::step reads or writes) equals that of one or two
// frames before and that repeat has been watched for as long as a positional
// repeat must last: a frame is a function of that state, so from then on the
// run would only go round the same cycle, and the figures cannot change.
Run run_scene(const Setup& s, const Config& c, long frames, bool shortcut);

}  // namespace bench::accuracy
