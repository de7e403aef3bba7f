// SPDX-License-Identifier: MIT
#include "categories.hpp"

#include "keys.hpp"
#include "plist.hpp"

namespace ds::guile {

CategoryNames CategoryNames::of(SCM category, SCM collides_with) {
    CategoryNames n;
    if (!SCM_UNBNDP(category)) n.category = SCM_UNPACK(category);
    if (SCM_UNBNDP(collides_with)) return n;
    n.count = 0;
    for (SCM p = collides_with; scm_is_pair(p); p = SCM_CDR(p)) {
        if (n.count == kInline) {
            n.count = kLong;
            break;
        }
        n.names[n.count++] = SCM_UNPACK(SCM_CAR(p));
    }
    return n;
}

CategoryTable::CategoryTable() {
    names_[0] = SCM_UNPACK(keys->default_category);
    count_ = 1;
}

bool CategoryTable::index_of(SCM key, uint64_t name, uint8_t& index, Failure& f) {
    for (int i = 0; i < count_; ++i)
        if (names_[i] == name) {
            index = static_cast<uint8_t>(i);
            return true;
        }
    if (count_ == kMaxCategories) {
        // The symbol is alive: a plist of this call holds it.
        fail(f, "out-of-range", scm_list_3(key, scm_from_int(kMaxCategories), SCM_PACK(name)),
             "entity key ~S: a frame holds at most ~S categories ('default included), and ~S is one more");
        return false;
    }
    names_[count_] = name;
    index = static_cast<uint8_t>(count_++);
    return true;
}

bool CategoryTable::mask_of(SCM list, uint64_t& mask, Failure& f) {
    mask = 0;
    for (SCM p = list; scm_is_pair(p); p = SCM_CDR(p)) {
        uint8_t index = 0;
        if (!index_of(keys->key[kCollidesWith], SCM_UNPACK(SCM_CAR(p)), index, f)) return false;
        mask |= uint64_t{1} << index;
    }
    return true;
}

bool CategoryTable::assign(SCM category, SCM collides_with, Body& b, Failure& f) {
    return assign_from(CategoryNames::of(category, collides_with), collides_with, b, f);
}

bool CategoryTable::assign(const CategoryNames& n, SCM entity, Body& b, Failure& f) {
    const bool long_list = n.count == CategoryNames::kLong;
    return assign_from(n, long_list ? plist_get(entity, keys->key[kCollidesWith], SCM_EOL) : SCM_EOL, b, f);
}

bool CategoryTable::assign_from(const CategoryNames& n, SCM long_list, Body& b, Failure& f) {
    b.category = {};
    b.collides_with = {};
    if (n.category != 0 && !index_of(keys->key[kCategory], n.category, b.category.index, f)) return false;
    if (n.count == CategoryNames::kAbsent) return true;
    if (n.count == CategoryNames::kLong) return mask_of(long_list, b.collides_with.bits, f);
    uint64_t mask = 0;
    for (int i = 0; i < n.count; ++i) {
        uint8_t index = 0;
        if (!index_of(keys->key[kCollidesWith], n.names[i], index, f)) return false;
        mask |= uint64_t{1} << index;
    }
    b.collides_with.bits = mask;
    return true;
}

}  // namespace ds::guile
