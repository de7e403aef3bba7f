#include "batch.hpp"

#include <memory>

#include "plist.hpp"

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

bool decode_batch(SCM entities, Batch& batch, Failure& f) {
    batch.before.clear();
    batch.bodies.clear();
    batch.has_tween.clear();
    batch.writes.clear();
    SCM p = entities;
    for (; scm_is_pair(p); p = SCM_CDR(p)) {
        Decoded d;
        if (!decode_entity(SCM_CAR(p), d, f)) return false;
        batch.before.push_back(d.body);
        batch.has_tween.push_back(scm_is_true(d.tween));
        batch.writes.push_back(FirstWrites{.watched = watched_fields(d)});
    }
    if (!scm_is_null(p)) {
        fail(f, "wrong-type-arg", scm_list_1(entities), "expected a list of entities, got ~S");
        return false;
    }
    batch.bodies = batch.before;
    return true;
}

SCM encode_batch(SCM entities, const Batch& batch) {
    // Find the last entity that changed: the spine is copied up to it.
    size_t last = 0;
    for (size_t i = 0; i < batch.size(); ++i)
        if (changed_fields(batch.before[i], batch.bodies[i]) != 0 || batch.writes[i].count != 0)
            last = i + 1;
    if (last == 0) return entities;
    SCM head = SCM_EOL, tail = SCM_BOOL_F, p = entities;
    for (size_t i = 0; i < last; ++i, p = SCM_CDR(p)) {
        Edit edits[16];
        SCM plist = SCM_CAR(p);
        SCM entity = rewrite_plist(plist, edits, field_edits(batch.before[i], batch.bodies[i], edits, &batch.writes[i]));
        SCM cell = scm_cons(entity, SCM_EOL);
        if (scm_is_false(tail)) head = cell;
        else scm_set_cdr_x(tail, cell);
        tail = cell;
    }
    scm_set_cdr_x(tail, p);
    return head;
}

}  // namespace ds::guile
