// A whole entity list decoded into bodies, and turned back into a list that
// keeps every unchanged entity (and the unchanged tail of the list) as it was.
#pragma once
#include <libguile.h>

#include <cstdint>
#include <vector>

#include "body.hpp"
#include "failure.hpp"
#include "frame.hpp"

namespace ds::guile {

struct Batch {
    std::vector<Body> before;  // as decoded
    std::vector<Body> bodies;  // what the steps work on
    std::vector<uint8_t> has_tween;
    std::vector<FirstWrites> writes;  // per body: watched fields and first writes
    std::vector<Body> frame_start;  // before the tweens, for ground detection
    Frame frame;               // the core's scratch for whole frames

    size_t size() const { return bodies.size(); }
};

// Decodes a proper list of entity plists. No SCM is kept: the list itself
// (the caller's argument) is walked again to encode.
bool decode_batch(SCM entities, Batch& batch, Failure& f);

// The entity list after the steps: entities whose bodies did not change are
// the same objects, the spine after the last changed entity is shared, and
// the list itself comes back when nothing changed.
SCM encode_batch(SCM entities, const Batch& batch);

// A scratch Batch for the current native call. Nested calls (a Scheme
// callback stepping another scene) get their own; the lease is returned by a
// dynwind handler, so a Scheme error unwinding through the call cannot leak it.
Batch& lease_batch();

}  // namespace ds::guile
