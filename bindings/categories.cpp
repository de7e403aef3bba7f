#include "categories.hpp"

#include "keys.hpp"

namespace ds::guile {

CategoryTable::CategoryTable() {
    names_[0] = SCM_UNPACK(keys->default_category);
    count_ = 1;
}

bool CategoryTable::bit_of(SCM key, SCM name, uint64_t& bit, Failure& f) {
    const uint64_t raw = SCM_UNPACK(name);
    for (int i = 0; i < count_; ++i)
        if (names_[i] == raw) {
            bit = uint64_t{1} << i;
            return true;
        }
    if (count_ == kMaxCategories) {
        fail(f, "out-of-range", scm_list_3(key, scm_from_int(kMaxCategories), name),
             "entity key ~S: a frame holds at most ~S categories ('default included), and ~S is one more");
        return false;
    }
    names_[count_] = raw;
    bit = uint64_t{1} << count_++;
    return true;
}

bool CategoryTable::assign(SCM category, SCM collides_with, Body& b, Failure& f) {
    b.category = {};
    b.collides_with = {};
    if (!SCM_UNBNDP(category) && !bit_of(keys->key[kCategory], category, b.category.bits, f)) return false;
    if (SCM_UNBNDP(collides_with)) return true;
    uint64_t mask = 0;
    for (SCM p = collides_with; scm_is_pair(p); p = SCM_CDR(p)) {
        uint64_t bit = 0;
        if (!bit_of(keys->key[kCollidesWith], SCM_CAR(p), bit, f)) return false;
        mask |= bit;
    }
    b.collides_with.bits = mask;
    return true;
}

}  // namespace ds::guile
