// SPDX-License-Identifier: MIT
// The per-entity motion steps (semantics §4), each guarded and skippable exactly as
// default-engine-update would apply it. They read and write one body, and
// return whether they applied (false: guarded out or skipped).
#pragma once
#include "body.hpp"
#include "constants.hpp"
#include "export.hpp"

namespace ds {


// A sub-frame's share of a frame (beyond the seed: make-game substeps: k).
// The seed's frame is whole (h = 1) and its steps stay exactly as they were;
// with k sub-frames each is h = 1/k of a frame, and a per-frame rate such as
// a velocity or gravity advances by rate·h, computed as a flonum.
struct SubStep {
    double h = 1;
    // A sub-frame after the first: the contact report (#:blocked) adds what
    // it finds to what the frame's earlier sub-frames found (semantics §10).
    bool gather = false;
    // A move that carries a rider with its carrier (semantics §11), not the
    // body's own: it never snaps down a ramp (§12).
    bool carried = false;

    static SubStep of_frame(int k) { return {k <= 1 ? 1.0 : 1.0 / k}; }
    bool whole() const { return h == 1; }
    Num share(Num rate) const { return whole() ? rate : Num::flonum(rate.v * h); }
};

// vy += ay, then ay = 0 (semantics §4). Needs #:gravity?; skipped by 'acceleration.
DOWNSTROKE_API bool apply_acceleration(Body& b);
// vy += gravity × #:gravity-scale (·h), gravity being the scene's (the
// seed's *gravity* by default; semantics §4, §14). Needs #:gravity?; skipped by 'gravity.
DOWNSTROKE_API bool apply_gravity(Body& b, SubStep s = {}, Num gravity = Num::integer(kGravity));
// Whether gravity pulls the body down (gravity × scale > 0): only then may
// a resting contact (FrameOptions::resting_contacts) hold it still.
inline bool pulled_down(const Body& b, Num gravity) {
    const double s = b.gravity_scale.n.v;
    return gravity.v != 0 && s != 0 && (gravity.v > 0) == (s > 0);
}
// #:drag (·h) moves vx and vy toward 0, never past it; then #:max-vx and
// #:max-vy clamp them (semantics §14). Needs one of the keys; skipped by
// 'speed-limits. Stores both velocities every time: the write back to an
// entity skips a value equal, in value and exactness, to the one read.
DOWNSTROKE_API bool apply_speed_limits(Body& b, SubStep s = {});
// x += vx (·h; in a sub-frame a zero velocity moves nothing; semantics §4);
// skipped by 'velocity-x.
DOWNSTROKE_API bool apply_velocity_x(Body& b, SubStep s = {});
// y += vy (·h; semantics §4); skipped by 'velocity-y.
DOWNSTROKE_API bool apply_velocity_y(Body& b, SubStep s = {});
// The legacy step: both axes, each skippable on its own (semantics §4).
DOWNSTROKE_API bool apply_velocity(Body& b);

}  // namespace ds
