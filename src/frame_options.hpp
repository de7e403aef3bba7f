// SPDX-License-Identifier: MIT
// What a whole frame runs under besides the bodies and the map.
#pragma once
#include "constants.hpp"
#include "number.hpp"
#include "tiles.hpp"

namespace ds {

struct FrameOptions {
    CollisionMode mode = CollisionMode::Swept;
    PushRule push = PushRule::Clipped;  // push-apart against the map (§4)
    double dt = 1000.0 / 60.0;  // ms; only tweens use it
    // Beyond the seed. substeps: the physics after the tweens runs k times,
    // each a 1/k sub-frame (SubStep), the one-shot acceleration in the first.
    // resting_contacts: still bodies resting exactly on a tile or a still
    // body skip gravity and hold up what lands on them (rests_on_tile,
    // resolve_pair).
    int substeps = 1;
    bool resting_contacts = false;
    // The scene's gravity (make-scene gravity:, semantics §14), px/frame²:
    // the seed's *gravity* unless a scene sets another.
    Num gravity = Num::integer(kGravity);

    // The options physics reads (all but dt, which only tweens use).
    bool same_physics(const FrameOptions& o) const {
        return mode == o.mode && push == o.push && substeps == o.substeps && resting_contacts == o.resting_contacts &&
               same(gravity, o.gravity);
    }
};

}  // namespace ds
