// Misspelt entity keys: a keyword the engine does not read but that is a
// slip away from one it does (#:sensr? for #:sensor?) silently turns a
// behaviour off. Decoding notices each such key, and the game reports it
// (engine.scm, take-key-slips!).
//
// Cost: each distinct unknown keyword is classified once per thread (its
// name against the engine's keys) and remembered by address in a small
// open-addressed table, so decoding pays one probe per unknown key, and only
// for the entities it decodes at all (a cached entity is not decoded again).
#pragma once
#include <libguile.h>

#include <cstddef>
#include <cstdint>

namespace ds::guile {

// What decoding an entity found: up to kMaxSlipsPerEntity near misses (more
// are noticed when the first are fixed), as slip-table slots.
struct EntitySlips {
    static constexpr uint8_t kMaxSlipsPerEntity = 8;
    uint16_t slot[kMaxSlipsPerEntity];
    uint8_t count = 0;
};

// Called by decode_entity for a keyword that is not a physics key: notes it
// in `out` when it is a near miss of an engine key.
void note_unknown_key(SCM keyword, EntitySlips& out);

// Queues the slips of the entity at `index` of a list (its #:id `id`, or #f)
// to be taken by %take-key-slips: each key once until taken.
void queue_slips(const EntitySlips& slips, size_t index, SCM id);

// Whether a key name is a near miss of the engine key `known`, which it is
// not: the rule docs/entities.org states. Exposed for the bindings' tests.
bool near_miss(const char* name, size_t name_len, const char* known);

}  // namespace ds::guile
