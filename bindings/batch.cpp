// SPDX-License-Identifier: MIT
#include "batch.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>

#include "cons.hpp"
#include "keys.hpp"
#include "list_walk.hpp"
#include "plist.hpp"
#include "pushed_pairs.hpp"

namespace ds::guile {

namespace {

thread_local std::vector<std::unique_ptr<Batch>> pool;
thread_local size_t in_use = 0;

void release_batch(void*) { --in_use; }

}  // namespace

Batch& lease_batch() {
    if (in_use == pool.size()) pool.push_back(std::make_unique<Batch>());
    Batch& b = *pool[in_use++];
    scm_dynwind_unwind_handler(release_batch, nullptr, SCM_F_WIND_EXPLICITLY);
    return b;
}

namespace {

// `vector` (a protected Guile vector, or #f) grown to `size` slots, its
// entries kept and the new ones `fill`; the old one is unprotected.
void grow_protected(SCM& vector, size_t size, SCM fill) {
    const size_t have = scm_is_true(vector) ? SCM_SIMPLE_VECTOR_LENGTH(vector) : 0;
    SCM grown = scm_c_make_vector(size, fill);
    for (size_t i = 0; i < have; ++i) SCM_SIMPLE_VECTOR_SET(grown, i, SCM_SIMPLE_VECTOR_REF(vector, i));
    scm_gc_protect_object(grown);
    if (scm_is_true(vector)) scm_gc_unprotect_object(vector);
    vector = grown;
}

// Room for n entries in the cache vector (grown by doubling, re-protected).
void reserve_cache(Batch& batch, size_t n) {
    const size_t have = scm_is_true(batch.cache) ? SCM_SIMPLE_VECTOR_LENGTH(batch.cache) : 0;
    if (n <= have) return;
    const size_t size = std::max(n, 2 * have);
    grow_protected(batch.cache, size, SCM_BOOL_F);
    grow_protected(batch.reported, 2 * size, SCM_UNDEFINED);
    grow_protected(batch.reporting, 2 * size, SCM_UNDEFINED);
    batch.cached.resize(size);
    batch.category_names.resize(size);
    batch.known.resize(size);
}

// The #:id of an entity that failed to decode, when it is a name worth
// printing (a symbol, string or number), else #f. The plist may be
// malformed or circular: the walk stops at either.
SCM printable_id(SCM plist) {
    Tortoise tortoise;
    for (SCM p = plist; scm_is_pair(p) && scm_is_pair(SCM_CDR(p)); p = SCM_CDR(SCM_CDR(p))) {
        if (tortoise.caught(p)) break;
        if (!scm_is_eq(SCM_CAR(p), keys->key[kId])) continue;
        const SCM id = SCM_CAR(SCM_CDR(p));
        return scm_is_symbol(id) || scm_is_string(id) || scm_is_number(id) ? id : SCM_BOOL_F;
    }
    return SCM_BOOL_F;
}

// A list's caller needs to know which entity was refused: the failure's
// message gains "(entity i of the list[, #:id x])".
void name_failed_entity(Failure& f, size_t index, SCM entity) {
    const SCM id = printable_id(entity);
    const char* suffix = scm_is_true(id) ? " (entity ~S of the list, #:id ~S)" : " (entity ~S of the list)";
    const char* said = f.message;
    f.failed = false;  // rewritten in place, with the same key
    fail(f, f.key, f.irritants, "%s%s", said, suffix);
    const SCM more = scm_is_true(id) ? scm_list_2(scm_from_size_t(index), id) : scm_list_1(scm_from_size_t(index));
    f.irritants = scm_append(scm_list_2(f.irritants, more));
}

}  // namespace

bool decode_batch(SCM entities, Batch& batch, Failure& f, CategoryTable* table) {
    CategoryTable own;
    CategoryTable& categories = table ? *table : own;
    batch.has_tween.clear();
    batch.writes.clear();
    batch.hit.clear();
    batch.reports = 0;
    batch.contact_bodies = 0;
    size_t i = 0;
    SCM p = entities;
    Tortoise tortoise;
    for (; scm_is_pair(p); p = SCM_CDR(p), ++i) {
        if (tortoise.caught(p)) {
            fail_circular(f, "entities", "a list of entities", entities);
            return false;
        }
        SCM e = SCM_CAR(p);
        reserve_cache(batch, i + 1);
        CachedEntity& c = batch.cached[i];
        const bool hit = scm_is_eq(SCM_SIMPLE_VECTOR_REF(batch.cache, i), e);
        if (!hit) {
            Decoded d;
            if (!decode_entity(e, d, f) || !categories.assign(d.category, d.collides_with, d.body, f)) {
                name_failed_entity(f, i, e);
                return false;
            }
            if (d.slips.count != 0) [[unlikely]] queue_slips(d.slips, i, printable_id(e));
            c = {d.places, watched_fields(d), scm_is_true(d.tween), d.body.reports_pairs(), d.categorized()};
            if (c.categorized) batch.category_names[i] = CategoryNames::of(d.category, d.collides_with);
            batch.known[i] = d.body;
            SCM_SIMPLE_VECTOR_SET(batch.cache, i, e);
            SCM_SIMPLE_VECTOR_SET(batch.reported, 2 * i, d.touching);
            SCM_SIMPLE_VECTOR_SET(batch.reported, 2 * i + 1, d.standing_on);
            batch.settling.forget(i);  // the mark was another entity's
        } else if (c.categorized && !categories.assign(batch.category_names[i], e, batch.known[i], f)) {
            // Bits are this call's: a cached body is given them again.
            name_failed_entity(f, i, e);
            return false;
        }
        batch.hit.push_back(hit);
        batch.contact_bodies += c.contacts;
        batch.has_tween.push_back(c.has_tween);
        batch.writes.push_back(FirstWrites{.watched = c.watched});
    }
    if (!scm_is_null(p)) {
        fail(f, "wrong-type-arg", scm_list_1(entities), "expected a list of entities, got ~S");
        return false;
    }
    batch.bodies.assign(batch.known.begin(), batch.known.begin() + static_cast<std::ptrdiff_t>(i));
    return true;
}

void plan_sleep(Batch& batch, const TileGrid* grid, const FrameOptions& opts) {
    batch.all_settled = false;  // until this frame completes (note_settled)
    batch.colliders = any_collider(batch.bodies);
    // An entity eq? to the one the last frame left is the body it left
    // (the cache's decoding of it).
    batch.fit.resize(batch.size());
    for (size_t i = 0; i < batch.size(); ++i) batch.fit[i] = batch.hit[i] && !batch.has_tween[i];
    batch.keep_groups = batch.groups_formed;
    batch.groups_formed = false;  // until this frame completes (note_settled)
    const bool same = batch.settling.begin(batch.size(), SettleConditions::of(grid, opts));
    batch.keep_groups &= same;
    if (!same) return;
    for (size_t i = 0; i < batch.size(); ++i)
        batch.settling.plan(i, batch.hit[i], batch.has_tween[i], batch.bodies[i], batch.colliders);
}

void note_settled(Batch& batch) {
    batch.unchanged.resize(batch.size());
    for (size_t i = 0; i < batch.size(); ++i) {
        batch.settling.settle(i, !batch.changed[i], batch.has_tween[i], batch.bodies[i], batch.colliders);
        // A plist handed back as it came is the same body next frame, which
        // the same frame leaves the same again (settle.hpp's RestingGroups).
        batch.unchanged[i] = !batch.changed[i] && !batch.has_tween[i];
    }
    batch.frame.form_resting_groups(batch.bodies, batch.unchanged);
    batch.groups_formed = true;
    // Every entity settled or in a resting group: handed this list again,
    // no collider is awake to reach a group, so the frame steps nobody.
    batch.some_grouped = false;
    batch.all_settled = true;
    for (size_t i = 0; i < batch.size() && batch.all_settled; ++i)
        if (!batch.settling.settled(i)) {
            batch.all_settled = batch.frame.resting_grouped(i);
            batch.some_grouped = true;
        }
}

bool frame_is_noop(const Batch& batch, SCM entities, const TileGrid* grid, const FrameOptions& opts) {
    // Groups sleep only while the overlay logs no pairs (Frame::plan_groups).
    return batch.all_settled && !(batch.some_grouped && pushed_pairs() != nullptr) &&
           scm_is_true(batch.last_result) &&
           scm_is_eq(SCM_SIMPLE_VECTOR_REF(batch.last_result, 0), entities) &&
           batch.settling.holds(SettleConditions::of(grid, opts));
}

void note_result(Batch& batch, SCM result) {
    if (scm_is_false(batch.last_result)) batch.last_result = scm_gc_protect_object(scm_c_make_vector(1, SCM_BOOL_F));
    SCM_SIMPLE_VECTOR_SET(batch.last_result, 0, result);
    batch.last_count = batch.size();
}

namespace {

// Exact zeros decode as +0.0 (every Num member); other members as they are.
void zero_as_decoded(Num& n) {
    if (n.exact && n.v == 0.0) n.v = 0.0;
}
template <class T>
void zero_as_decoded(T&) {}

// What decoding the entity just encoded at position i would give, so the
// next frame, handed that entity back, need not decode it. Every edited field
// now holds a fixnum, bignum or flonum, so it is present and no longer lossy;
// exact zeros are +0.0, as decoding makes them. Tweened entities are left to
// be decoded again: their #:tween changes outside the body.
// `placed`: the entity was rewritten in place order (rewrite_placed), so
// its keys sit where they sat, after the report fields put in front;
// otherwise they are found again. `edits` are
// those that made it: report values they wrote replace the ones kept.
void remember(Batch& batch, size_t i, SCM entity, bool placed, const Edit* edits, size_t n) {
    if (batch.has_tween[i]) return;
    for (size_t k = 0; k < n; ++k) {
        if (edits[k].field == kFieldBitTouching) SCM_SIMPLE_VECTOR_SET(batch.reported, 2 * i, edits[k].value);
        if (edits[k].field == kFieldBitStandingOn) SCM_SIMPLE_VECTOR_SET(batch.reported, 2 * i + 1, edits[k].value);
    }
    CachedEntity& c = batch.cached[i];
    Body& b = batch.known[i];
    b = batch.bodies[i];
#define DS_FIELD(Name, type, member, keyword, rule) zero_as_decoded(b.member);
#define DS_KEY(Name, type, member, keyword, rule) zero_as_decoded(b.member);
#include "body_fields.def"
    const uint32_t edited = batch.fields[i] | batch.writes[i].written();
    c.watched = static_cast<uint16_t>(c.watched & ~edited);
    if (!placed) {
        c.places = places_of(entity);
    } else {
        // The absent report fields went in front, each before the previous.
        // Which were absent is read before any shift: a shift can push a
        // placed key past kMaxPlace, and it must not be taken for one.
        static_assert(kFieldCount + 2 <= 32, "an edit list (encode_batch) fits the mask");
        uint32_t absent = 0;  // bit k: edits[k] went in front
        for (size_t k = 0; k < n; ++k)
            if (c.places.at[edits[k].field] == FieldPlaces::kUnplaced) absent |= 1u << k;
        for (size_t k = 0; k < n; ++k)
            if ((absent >> k) & 1u) c.places.put_in_front(edits[k].field);
    }
    SCM_SIMPLE_VECTOR_SET(batch.cache, i, entity);
}

// The pairs of an entity's plist that encoding will read: fetched some
// entities ahead, so that walking the plists is not one memory stall after
// another (a big scene's plists are far out of cache by the next frame).
// The collector hands a block's pairs out from the top down, so a plist
// rewritten last frame runs downward from its head: the lines fetched here
// hold the head and what was consed just before it. Fetching the lines
// below instead, or one more line and 16 entities ahead, measured no
// better (docs/benchmarks.org); dropping the prefetch, 2–10 % slower.
constexpr size_t kPrefetchAhead = 8;
void prefetch_plist(SCM plist) {
    const char* cell = reinterpret_cast<const char*>(SCM2PTR(plist));
    __builtin_prefetch(cell);
    __builtin_prefetch(cell + 64);
    __builtin_prefetch(cell + 128);
}


// The spine of the list encode_batch returns, allocated in runs of pairs
// taken one after another from the free list: the next frame walks it twice
// (decode_batch, then encode_batch's `p` and `ahead`), and a run sits in a
// few cache lines, where a pair consed after each rewritten plist takes a
// line of its own (at 10k entities, rain's decoding took a quarter less:
// docs/benchmarks.org).
// Short runs, so that each is still in cache while it is filled. Lives on
// the stack, where the collector sees its pairs.
class Spine {
public:
    // Appends entity; `left` counts the entities still to come, this one included.
    void append(SCM entity, size_t left) {
        if (ready_ == 0) open_run(std::min(kRun, left));
        SCM_SETCAR(next_, entity);  // a fresh pair: no check, and the collector needs no barrier
        next_ = SCM_CDR(next_);
        --ready_;
    }
    // The list, ending in `rest` (the entities after the last one appended).
    SCM finish(SCM rest) {
        SCM_SETCDR(tail_, rest);
        return head_;
    }

private:
    static constexpr size_t kRun = 32;  // 512 bytes of pairs

    void open_run(size_t n) {
        const SCM first = cons_(SCM_BOOL_F, SCM_EOL);
        SCM last = first;
        for (size_t k = 1; k < n; ++k) {
            const SCM pair = cons_(SCM_BOOL_F, SCM_EOL);
            SCM_SETCDR(last, pair);
            last = pair;
        }
        if (scm_is_false(tail_)) head_ = first;
        else SCM_SETCDR(tail_, first);
        tail_ = last;
        next_ = first;
        ready_ = n;
    }

    Conser cons_;
    SCM head_ = SCM_EOL, tail_ = SCM_BOOL_F, next_ = SCM_EOL;
    size_t ready_ = 0;  // pairs of the current run still to fill
};

// Names contact entity i's report values for this call (Batch::reporting).
void name_report(Batch& batch, size_t i, SCM names) {
    const Body& b = batch.bodies[i];
    const SCM touching =
        (batch.reports & kReportsTouching) ? touching_names(batch.contacts, i, names, b.contacts == kContactsSides) : SCM_UNDEFINED;
    const SCM standing =
        (batch.reports & kReportsStanding) && b.detects_ground() ? standing_name(b, names) : SCM_UNDEFINED;
    SCM_SIMPLE_VECTOR_SET(batch.reporting, 2 * i, touching);
    SCM_SIMPLE_VECTOR_SET(batch.reporting, 2 * i + 1, standing);
}

// The edits that rewrite entity i; when the call reports contacts (`reports`),
// a contact entity's report values too (named by name_report), compared
// with those its cached plist holds (Batch::reported).
size_t entity_edits(const Batch& batch, size_t i, bool reports, Edit* edits) {
    const Body& b = batch.bodies[i];
    const size_t n = field_edits(batch.fields[i], b, edits, &batch.writes[i]);
    if (!reports || !b.contacts) return n;
    return report_edits(SCM_SIMPLE_VECTOR_REF(batch.reported, 2 * i), SCM_SIMPLE_VECTOR_REF(batch.reported, 2 * i + 1),
                        SCM_SIMPLE_VECTOR_REF(batch.reporting, 2 * i),
                        SCM_SIMPLE_VECTOR_REF(batch.reporting, 2 * i + 1), edits, n);
}

// The names a call's contact report uses, or #f when it writes no report.
SCM report_names(SCM entities, const Batch& batch) {
    if (batch.reports == 0 || batch.contact_bodies == 0) return SCM_BOOL_F;
    thread_local std::vector<int64_t> ids;
    ids.clear();
    for (const Body& b : batch.bodies) ids.push_back(b.id);
    return entity_names(entities, ids);
}

}  // namespace

SCM encode_batch(SCM entities, Batch& batch, Failure& f) {
    // Find the last entity that changed: the spine is copied up to it.
    size_t last = 0;
    batch.changed.resize(batch.size());
    batch.fields.resize(batch.size());
    const SCM names = report_names(entities, batch);
    Edit edits[kFieldCount + 2];
    const bool reports = scm_is_true(names);
    for (size_t i = 0; i < batch.size(); ++i) {
        batch.fields[i] = changed_fields(batch.known[i], batch.bodies[i]);
        if (!check_finite(batch.bodies[i], batch.fields[i], f)) return entities;
        batch.changed[i] = batch.fields[i] != 0 || batch.writes[i].count != 0;
        // A contact entity's report may change what the plist holds, or not.
        if (reports && batch.bodies[i].contacts) {
            name_report(batch, i, names);
            // A report key the body marks may still be written as it was (no
            // edit): unless another field changed, find out.
            constexpr uint32_t kNamedFields = kFieldTouching | kFieldStandingOn;
            const bool other = ((batch.fields[i] | batch.writes[i].written()) & ~kNamedFields) != 0;
            batch.changed[i] = other || entity_edits(batch, i, reports, edits) != 0;
        }
        if (batch.changed[i]) last = i + 1;
    }
    if (last == 0) return entities;
    SCM p = entities;
    SCM ahead = entities;
    for (size_t j = 0; j < kPrefetchAhead && j < last; ++j, ahead = SCM_CDR(ahead))
        if (batch.changed[j]) prefetch_plist(SCM_CAR(ahead));
    Spine spine;
    for (size_t i = 0; i < last; ++i, p = SCM_CDR(p)) {
        if (i + kPrefetchAhead < last) {
            if (batch.changed[i + kPrefetchAhead]) prefetch_plist(SCM_CAR(ahead));
            ahead = SCM_CDR(ahead);
        }
        SCM plist = SCM_CAR(p), entity = plist;
        if (batch.changed[i]) {
            const size_t n = entity_edits(batch, i, reports, edits);
            const bool placed = all_placed(edits, n, batch.cached[i].places);
            entity = placed ? rewrite_placed(plist, edits, n, batch.cached[i].places) : rewrite_plist(plist, edits, n);
            remember(batch, i, entity, placed, edits, n);
        }
        spine.append(entity, last - i);
    }
    return spine.finish(p);
}

}  // namespace ds::guile
