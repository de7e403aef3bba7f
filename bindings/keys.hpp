// SPDX-License-Identifier: MIT
// The keywords and symbols the bindings compare against, interned once after
// Guile has started (never in namespace-scope statics: interning needs a
// running Guile). Each is protected from the collector when interned, since
// nothing else may hold on to it.
#pragma once
#include <libguile.h>

#include <cstdint>

#include "body.hpp"

namespace ds::guile {

// The physics keys of an entity plist: one per row of src/body_fields.def,
// in its order (k<Name>: kX, kVy, kLocalX, kOnGround, kGroupId, …), then the
// keys that are not Body members. A bit index of Decoded::present.
enum PhysKey : uint8_t {
#define DS_FIELD(Name, type, member, keyword, rule) k##Name,
#define DS_KEY(Name, type, member, keyword, rule) k##Name,
#include "body_fields.def"
    kTween,  // #:tween, kept as it is (Decoded::tween)
    kPhysKeyCount,
    kNotPhysics = 0xff,
};
static_assert(kPhysKeyCount <= 64, "Decoded::present holds one bit per PhysKey");

struct Keys {
    SCM key[kPhysKeyCount];
    SCM skip_symbol[kSkipCount];  // by bit index of ds::Skip
    SCM swept, discrete;
    SCM clipped, seed;  // the push rules (PushRule)
    SCM side_symbol[4];  // left right up down: by bit index of ds::Side
    SCM sides;           // #:contacts? 'sides (ds::kContactsSides)
    SCM default_category;  // 'default (semantics §13)

    // Which physics key a keyword (or any object) is, or kNotPhysics: one
    // probe of a small open-addressed table on the object's address, as it
    // runs for every key of every entity of every frame.
    uint8_t lookup(SCM obj) const {
        for (size_t slot = hash(obj);; slot = (slot + 1) & (kSlots - 1)) {
            if (scm_is_eq(slot_key[slot], obj)) return slot_index[slot];
            if (scm_is_false(slot_key[slot])) return kNotPhysics;
        }
    }

    static constexpr size_t kSlots = 64;
    static size_t hash(SCM obj) {
        return static_cast<size_t>((SCM_UNPACK(obj) >> 3) * 0x9E3779B97F4A7C15ull >> 58);
    }
    SCM slot_key[kSlots];
    uint8_t slot_index[kSlots];
};

// Valid after init_keys().
extern const Keys* keys;
void init_keys();

const char* key_name(uint8_t k);  // "x", "gravity?", … without the #:

}  // namespace ds::guile
