// One whole engine pass over an entity list in one native call.
#include <algorithm>

#include "args.hpp"
#include "batch.hpp"
#include "keys.hpp"
#include "registry.hpp"
#include "scm_number.hpp"
#include "tilemap_type.hpp"
#include "tween_step.hpp"

namespace ds::guile {

namespace {

// The tween stage: entities with a tween are advanced (on-complete may
// replace them); the rest stay as they are. Returns the list to step.
SCM step_list_tweens(SCM entities, const Batch& batch, double dt, Failure& f) {
    if (std::none_of(batch.has_tween.begin(), batch.has_tween.end(), [](uint8_t t) { return t; }))
        return entities;
    SCM out = SCM_EOL;
    bool changed = false;
    size_t i = 0;
    for (SCM p = entities; scm_is_pair(p) && !f; p = SCM_CDR(p), ++i) {
        SCM e = SCM_CAR(p);
        SCM stepped = batch.has_tween[i] ? advance_entity_tween(e, dt, f) : e;
        changed |= !scm_is_eq(stepped, e);
        out = scm_cons(stepped, out);
    }
    return changed ? scm_reverse_x(out, SCM_EOL) : entities;
}

SCM step_entities(SCM entities, SCM tilemap, SCM dt, SCM mode) {
    Failure f{.proc = "step-scene"};
    SCM result = entities;
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    {
        FrameOptions opts;
        const TileGrid* grid = nullptr;
        Batch& batch = lease_batch();
        if (dt_from_scm(dt, opts.dt, f) && grid_from_scm(tilemap, grid, f) && mode_from_scm(mode, opts.mode, f) &&
            decode_batch(entities, batch, f)) {
            SCM list = step_list_tweens(entities, batch, opts.dt, f);
            const bool tweened = !scm_is_eq(list, entities);
            if (tweened) batch.frame_start = batch.before;  // the scene before the tweens
            if (!f && (!tweened || decode_batch(list, batch, f))) {
                batch.frame.step_physics(batch.bodies, grid, opts,
                                         tweened ? std::span<const Body>(batch.frame_start)
                                                 : std::span<const Body>(),
                                         batch.writes);
                result = encode_batch(list, batch);
            }
        }
    }
    scm_dynwind_end();
    if (f) raise(f);
    return result;
}

}  // namespace

void register_frame_procedures() {
    define_procedure("%step-entities", 4, 0, 0, (Subr)step_entities,
                     "(entities tilemap dt mode): the whole default-engine-update pass over a list of "
                     "entities: tweens, motion, tiles, ground, push-apart, groups.");
}

}  // namespace ds::guile
