// SPDX-License-Identifier: MIT
// One whole engine pass over an entity list in one native call.
#include <algorithm>

#include "args.hpp"
#include "contacts.hpp"
#include "batch.hpp"
#include "plist.hpp"
#include "pushed_pairs.hpp"
#include "keys.hpp"
#include "registry.hpp"
#include "scm_number.hpp"
#include "detail/stopwatch.hpp"
#include "gc_clock.hpp"
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
    // advance_entity_tween calls Scheme: see step_entities.
    static_assert(survives_longjmp<decltype(out), decltype(changed), decltype(i), decltype(batch)>);
    for (SCM p = entities; scm_is_pair(p) && !f; p = SCM_CDR(p), ++i) {
        SCM e = SCM_CAR(p);
        SCM stepped = batch.has_tween[i] ? advance_entity_tween(e, dt, f) : e;
        changed |= !scm_is_eq(stepped, e);
        out = scm_cons(stepped, out);
    }
    return changed ? scm_reverse_x(out, SCM_EOL) : entities;
}

// The last whole frame stepped on this thread: the core's per-step figures
// plus the boundary's own (plist decoding and encoding, the tween stage) and
// what the collector cost during the call. The boundary's times leave out
// the collections inside them, which `collect` reports on their own.
struct LastFrame {
    FrameStats core;
    StepStats decode, encode;  // encode: processed = entities rewritten
    GcReading collect;
    size_t entities = 0;
};
thread_local LastFrame last_frame;

// Wall time of one phase of a frame, less the collections that ran inside it.
struct PhaseTimer {
    Clock::time_point t0 = Clock::now();
    uint64_t gc0 = gc_ns();
    double lap() {
        const Clock::time_point t1 = Clock::now();
        const uint64_t gc1 = gc_ns();
        const double ms = ms_between(t0, t1) - static_cast<double>(gc1 - gc0) / 1e6;
        t0 = t1;
        gc0 = gc1;
        return ms > 0 ? ms : 0;
    }
};

// The pairs of the last step-scene on this thread with a contact entity
// (semantics §10), by index into the list it returned: %frame-contacts
// names them.
thread_local std::vector<IndexPair> last_pairs;
thread_local std::vector<uint8_t> last_sides;  // by last_pairs: the earlier body's side
thread_local std::vector<int64_t> last_ids;  // the bodies' #:id tags, for naming them

// After the frame: what push-apart logged, when some entity reports contacts.
void gather_contacts(Batch& batch) {
    if (batch.contact_bodies == 0) return;
    batch.contacts.gather(batch.frame.contact_pairs(), batch.frame.contact_sides(), batch.bodies);
    batch.reports = kReportsTouching | kReportsStanding;
    last_pairs = batch.contacts.pairs;
    last_sides = batch.contacts.pair_sides;
    last_ids.clear();
    for (const Body& b : batch.bodies) last_ids.push_back(b.id);
}

}  // namespace

PairLog*& pushed_pairs() {
    thread_local PairLog* log = nullptr;
    return log;
}

namespace {

SCM step_entities(SCM entities, SCM tilemap, SCM dt, SCM mode, SCM substeps, SCM resting, SCM gravity,
                  SCM push) {
    Failure f{"step-scene"};
    SCM result = entities;
    if (PairLog* log = pushed_pairs()) log->clear();  // the overlay shows this frame's pairs
    last_pairs.clear();
    last_sides.clear();
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    guarded(f, nullptr, [&] {
        FrameOptions opts;
        opts.resting_contacts = !SCM_UNBNDP(resting) && scm_is_true(resting);
        const TileGrid* grid = nullptr;
        Batch& batch = lease_batch();  // owned by the pool, returned by the dynwind handler
        LastFrame stats;
        const GcReading gc0 = gc_reading();
        PhaseTimer timer;
        CategoryTable categories;  // one for both decodings: the same name, the same bit
        // The tween stage calls Scheme (custom easings, on-complete): an error
        // or escape there longjmps over this frame, these locals included.
        static_assert(survives_longjmp<decltype(opts), decltype(grid), decltype(batch), decltype(stats),
                                       decltype(gc0), decltype(timer), decltype(categories)>);
        if (dt_from_scm(dt, opts.dt, f) && grid_from_scm(tilemap, grid, f) && mode_from_scm(mode, opts.mode, f) &&
            substeps_from_scm(substeps, opts.substeps, f) && gravity_from_scm(gravity, opts.gravity, f) &&
            push_rule_from_scm(push, opts.push, f) &&
            frame_is_noop(batch, entities, grid, opts)) {
            // Every entity settled and is handed back as left: skip even the decoding.
            stats.entities = batch.last_count;
            stats.decode.skipped = stats.encode.skipped = batch.last_count;
            for (StepStats& s : stats.core.step) s.skipped = batch.last_count;
            stats.collect = gc_reading() - gc0;
            last_frame = stats;
        } else if (!f && decode_batch(entities, batch, f, &categories)) {
            stats.decode.ms = timer.lap();
            SCM list = step_list_tweens(entities, batch, opts.dt, f);
            const bool tweened = !scm_is_eq(list, entities);
            const auto tweens = static_cast<uint64_t>(
                std::count(batch.has_tween.begin(), batch.has_tween.end(), uint8_t{1}));
            stats.core.step[kStepTweens] = {tweens, batch.size() - tweens, timer.lap()};
            // The scene before the tweens, which ground detection reads.
            if (tweened) batch.frame_start.assign(batch.before().begin(), batch.before().end());
            if (!f && (!tweened || decode_batch(list, batch, f, &categories))) {
                stats.decode.ms += timer.lap();
                plan_sleep(batch, grid, opts);
                batch.frame.note_pairs(pushed_pairs());
                batch.frame.step_physics_resting(batch.bodies, grid, opts,
                                                 tweened ? std::span<const Body>(batch.frame_start)
                                                         : std::span<const Body>(),
                                                 batch.writes, batch.settling.asleep(), batch.fit,
                                                 batch.keep_groups);
                gather_contacts(batch);
                timer.lap();  // the steps time themselves (batch.frame.stats())
                result = encode_batch(list, batch, f);
                if (!f) {
                    note_settled(batch);
                    note_result(batch, result);
                    stats.encode.ms = timer.lap();
                    const StepStats tween_stats = stats.core.step[kStepTweens];
                    stats.core = batch.frame.stats();
                    stats.core.step[kStepTweens] = tween_stats;
                    stats.entities = batch.size();
                    stats.decode.processed = batch.size();
                    stats.encode.processed = static_cast<uint64_t>(
                        std::count(batch.changed.begin(), batch.changed.end(), uint8_t{1}));
                    stats.encode.skipped = batch.size() - stats.encode.processed;
                    stats.collect = gc_reading() - gc0;
                    last_frame = stats;
                }
            }
        }
    });
    scm_dynwind_end();
    if (f) raise(f);
    return result;
}

// The last step-scene's pairs, named against the list it returned.
SCM frame_contacts(SCM entities) {
    if (last_pairs.empty()) return SCM_EOL;
    size_t needed = 0;
    for (const IndexPair& p : last_pairs) needed = std::max<size_t>(needed, p.second + 1u);
    if (scm_is_false(scm_list_p(entities)) || scm_to_size_t(scm_length(entities)) < needed) {
        Failure f{"step-scene"};
        fail(f, "wrong-type-arg", scm_list_1(entities), "expected the entity list the frame returned, got ~S");
        raise(f);
    }
    return pair_names(last_pairs, entity_names(entities, last_ids));
}

// The sides of the last step-scene's pairs, pair for pair (side_codes).
SCM frame_contact_sides() { return side_codes(last_sides); }

SCM step_stats(const char* name, const StepStats& s) {
    return scm_list_4(scm_from_utf8_symbol(name), scm_from_uint64(s.processed),
                      scm_from_uint64(s.skipped), scm_from_double(s.ms));
}

SCM frame_stats() {
    const LastFrame& l = last_frame;
    const SCM collect = scm_list_4(scm_from_utf8_symbol("collect"), scm_from_uint64(l.collect.collections),
                                   scm_from_uint64(l.collect.bytes),
                                   scm_from_double(static_cast<double>(l.collect.ns) / 1e6));
    SCM rows = scm_list_2(step_stats("encode", l.encode), collect);
    for (int id = kStepCount - 1; id >= 0; --id)
        rows = scm_cons(step_stats(step_name(static_cast<StepId>(id)), l.core.step[id]), rows);
    return scm_cons(step_stats("decode", l.decode), rows);
}

}  // namespace

void register_frame_procedures() {
    define_procedure<4, 4, 0, step_entities>("%step-entities",
        WrapperDoc{"(entities tilemap dt mode [substeps [resting-contacts? [gravity [push-rule]]]])", "step-scene", "(downstroke physics)"});
    define_procedure<1, 0, 0, frame_contacts>("%frame-contacts",
        WrapperDoc{"(entities) → ((name-a . name-b) …)", "step-scene", "(downstroke physics)"});
    define_procedure<0, 0, 0, frame_contact_sides>("%frame-contact-sides",
        WrapperDoc{"() → bytevector of side numbers, by %frame-contacts' pairs", "step-scene", "(downstroke physics)"});
    define_procedure<0, 0, 0, frame_stats>("%frame-stats",
        WrapperDoc{"() → ((step processed skipped ms) … (collect collections bytes ms))", "engine-stats", "(downstroke engine)"});
}

}  // namespace ds::guile
