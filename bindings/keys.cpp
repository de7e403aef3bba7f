// SPDX-License-Identifier: MIT
#include "keys.hpp"

#include "body.hpp"

namespace ds::guile {

namespace {

constexpr const char* kKeyNames[kPhysKeyCount] = {
#define DS_FIELD(Name, type, member, keyword, rule) keyword,
#define DS_KEY(Name, type, member, keyword, rule) keyword,
#include "body_fields.def"
    "tween",
};

Keys storage;

}  // namespace

const Keys* keys = nullptr;

const char* key_name(uint8_t k) { return k < kPhysKeyCount ? kKeyNames[k] : "?"; }

namespace {
SCM keep(SCM obj) { return scm_gc_protect_object(obj); }
}  // namespace

void init_keys() {
    if (keys) return;
    for (uint8_t k = 0; k < kPhysKeyCount; ++k) storage.key[k] = keep(scm_from_utf8_keyword(kKeyNames[k]));
    for (SCM& slot : storage.slot_key) slot = SCM_BOOL_F;
    for (uint8_t k = 0; k < kPhysKeyCount; ++k) {
        size_t slot = Keys::hash(storage.key[k]);
        while (scm_is_true(storage.slot_key[slot])) slot = (slot + 1) & (Keys::kSlots - 1);
        storage.slot_key[slot] = storage.key[k];
        storage.slot_index[slot] = k;
    }
    for (int bit = 0; bit < kSkipCount; ++bit)
        storage.skip_symbol[bit] = keep(scm_from_utf8_symbol(skip_name(static_cast<uint16_t>(1u << bit))));
    storage.swept = keep(scm_from_utf8_symbol("swept"));
    storage.discrete = keep(scm_from_utf8_symbol("discrete"));
    storage.clipped = keep(scm_from_utf8_symbol("clipped"));
    storage.seed = keep(scm_from_utf8_symbol("seed"));
    constexpr const char* kSides[4] = {"left", "right", "up", "down"};
    for (int bit = 0; bit < 4; ++bit) storage.side_symbol[bit] = keep(scm_from_utf8_symbol(kSides[bit]));
    storage.default_category = keep(scm_from_utf8_symbol("default"));
    storage.sides = keep(scm_from_utf8_symbol("sides"));
    keys = &storage;
}

}  // namespace ds::guile
