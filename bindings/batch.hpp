// SPDX-License-Identifier: MIT
// A whole entity list decoded into bodies, and turned back into a list that
// keeps every unchanged entity (and the unchanged tail of the list) as it was.
#pragma once
#include <libguile.h>

#include <cstdint>
#include <span>
#include <vector>

#include "body.hpp"
#include "detail/first_writes.hpp"
#include "categories.hpp"
#include "contact_report.hpp"
#include "failure.hpp"
#include "frame.hpp"
#include "plist.hpp"
#include "settle.hpp"
#include "tile_grid.hpp"

namespace ds::guile {

// What decoding an entity produced besides its body, kept for as long as
// the same plist (eq?) comes back: plists are values, so the same object
// decodes the same.
struct CachedEntity {
    FieldPlaces places;
    uint16_t watched = 0;
    bool has_tween = false;
    bool contacts = false;  // known[i].reports_pairs(), kept here so a cache hit need not read its body
    bool categorized = false;  // has #:category or #:collides-with: bits are set per call
};

struct Batch {
    // By position: the decoded body of the entity in cache slot i. After
    // decode_batch, its first size() bodies are the list as decoded (before());
    // a cache hit costs no copy, and encode_batch writes back only the bodies
    // that changed.
    std::vector<Body> known;
    std::vector<Body> bodies;  // what the steps work on
    std::vector<uint8_t> has_tween;
    std::vector<FirstWrites> writes;  // per body: watched fields and first writes
    std::vector<Body> frame_start;  // before the tweens, for ground detection
    Frame frame;               // the core's scratch for whole frames
    // The entities decoded last time, by position: a Guile vector (so the
    // collector sees them and they cannot be recycled into look-alikes),
    // protected while this Batch holds it, and their decodings.
    SCM cache = SCM_BOOL_F;
    // Beside it, by position: the #:touching and #:standing-on the cached
    // plist holds (slots 2i and 2i + 1; SCM_UNDEFINED when absent), so that
    // a frame compares its report with them without walking to them: an
    // author's keys often follow the engine's, and a walk to the far end of
    // every contact entity's plist took a quarter of the shots scene's frame
    // (docs/benchmarks.org). A Guile vector protected like `cache`.
    SCM reported = SCM_BOOL_F;
    // By position, the same two slots: the values this call reports (SCM_UNDEFINED
    // for a key it does not write), named once when encode_batch decides
    // what changed and used again when it rewrites. Protected likewise.
    SCM reporting = SCM_BOOL_F;
    std::vector<CachedEntity> cached;
    std::vector<CategoryNames> category_names;  // by position: set for the categorized ones
    std::vector<uint8_t> hit;    // by position: taken from the cache this time (as left)
    // By position: which entities settled, under which map and options, and
    // which the frame leaves asleep (settle.hpp).
    Settling settling;
    // Resting groups of colliders (settle.hpp), which batch.frame keeps:
    // by position, whether the entity enters as the last frame left it with
    // no tween (`fit`), and after the frame whether it left a stepped one so
    // (`unchanged`); whether the last frame's groups may sleep in this one
    // (the same conditions, and that frame formed them: a frame that failed
    // part-way formed none).
    std::vector<uint8_t> fit, unchanged;
    bool keep_groups = false, groups_formed = false;
    std::vector<uint8_t> changed;  // by position: encode_batch rewrote it
    std::vector<uint32_t> fields;  // by position: the Field bits that changed
    bool colliders = false;        // the frame has bodies that collide
    // The contact report (semantics §10): which keys this call writes on
    // contact entities (ReportKeys; decode_batch resets it) and the pairs.
    uint8_t reports = 0;
    size_t contact_bodies = 0;  // decoded with #:contacts? or #:sensor? (decode_batch counts them)
    ContactIndex contacts;
    // The list the last whole frame returned (slot 0 of a protected vector,
    // so it cannot be recycled into a look-alike at the same address), and
    // whether every entity in it had settled or is in a resting group (and
    // whether any relies on a group): handed that very list again under the
    // same map (revision) and options, the frame would change nothing.
    SCM last_result = SCM_BOOL_F;
    size_t last_count = 0;  // its length (the other calls sharing this Batch resize `bodies`)
    bool all_settled = false, some_grouped = false;

    size_t size() const { return bodies.size(); }
    // The list as decoded (valid from decode_batch until encode_batch).
    std::span<const Body> before() const { return {known.data(), bodies.size()}; }
};

// Decodes a proper list of entity plists. No SCM is kept: the list itself
// (the caller's argument) is walked again to encode.
// Categories (semantics §13) become bits through `table`, which a call that
// decodes several lists shares among them; without one, a table of its own.
bool decode_batch(SCM entities, Batch& batch, Failure& f, CategoryTable* table = nullptr);

// The entity list after the steps: entities whose bodies did not change are
// the same objects, the spine after the last changed entity is shared, and
// the list itself comes back when nothing changed.
// Also records which entities changed (Batch::changed). Fails, returning
// the list as it was, when a changed value left the range of a double.
SCM encode_batch(SCM entities, Batch& batch, Failure& f);

// Plans which entities a whole frame leaves asleep (settled, handed back as
// the same object, under the same map revision and options, still depending
// on no other entity), and after the frame (after encode_batch) records
// which entities settled. Both by position, in Batch::settling. Also
// what the frame's resting groups need (Batch::fit, keep_groups), and
// after the frame the groups the next one may keep.
void plan_sleep(Batch& batch, const TileGrid* grid, const FrameOptions& opts);
void note_settled(Batch& batch);

// Whether `entities` is the list the last whole frame returned, every entity
// of it settled, under the same map revision and options: the frame is a no-op.
bool frame_is_noop(const Batch& batch, SCM entities, const TileGrid* grid, const FrameOptions& opts);
// Records the list a whole frame returned (after note_settled).
void note_result(Batch& batch, SCM result);

// A scratch Batch for the current native call. Nested calls (a Scheme
// callback stepping another scene) get their own; the lease is returned by a
// dynwind handler, so a Scheme error unwinding through the call cannot leak it.
Batch& lease_batch();

}  // namespace ds::guile
