// SPDX-License-Identifier: MIT
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

// The unknown keywords seen on one thread, by address: each was classified
// once. Keywords are protected once remembered, so an address never comes
// to mean another keyword. The bound keeps a program that makes keywords
// without end (string->keyword per entity) from growing it: past it, new
// unknown keys go unchecked (docs/limits.org, "Entity keys").
struct SlipTable {
    static constexpr size_t kSlots = 1024;  // a power of two, at most half full
    static constexpr size_t kMaxKeys = 512;
    static constexpr uint8_t kFar = 0xff;  // not a slip (or an engine key the renderer reads)
    SCM key[kSlots];
    uint8_t suggestion[kSlots];  // the engine key it is a slip of, or kFar
    bool queued[kSlots];
    size_t used = 0;
    SCM pending = SCM_BOOL_F;  // a protected 1-slot vector: the queued reports, newest first

    SlipTable();
    static size_t hash(SCM obj) {
        return static_cast<size_t>((SCM_UNPACK(obj) >> 3) * 0x9E3779B97F4A7C15ull >> 54);
    }
    // Classifies and remembers a keyword met for the first time at the empty
    // `slot`; false when the table is full.
    bool add(SCM keyword, size_t slot);
};

SlipTable& this_thread_slips();

// Called by decode_entity for a keyword that is not a physics key: notes it
// in `out` when it is a near miss of an engine key. `t` is this thread's
// table, fetched at the entity's first unknown key (a thread-local costs a
// call in a shared library) and kept for the rest of its keys. Inline: it
// runs for every key of the author's own in every entity decoded.
inline void note_unknown_key(SlipTable*& t, SCM keyword, EntitySlips& out) {
    if (!t) t = &this_thread_slips();
    size_t slot = SlipTable::hash(keyword);
    for (;; slot = (slot + 1) & (SlipTable::kSlots - 1)) {
        if (scm_is_eq(t->key[slot], keyword)) break;
        if (scm_is_false(t->key[slot])) [[unlikely]] {
            if (!t->add(keyword, slot)) return;
            break;
        }
    }
    if (t->suggestion[slot] != SlipTable::kFar && out.count < EntitySlips::kMaxSlipsPerEntity) [[unlikely]]
        out.slot[out.count++] = static_cast<uint16_t>(slot);
}

// Queues the slips of the entity at `index` of a list (its #:id `id`, or #f)
// to be taken by %take-key-slips: each key once until taken.
void queue_slips(const EntitySlips& slips, size_t index, SCM id);

// Whether a key name is a near miss of the engine key `known`, which it is
// not: the rule docs/entities.org states. Exposed for the bindings' tests.
bool near_miss(const char* name, size_t name_len, const char* known);

}  // namespace ds::guile
