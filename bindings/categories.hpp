// SPDX-License-Identifier: MIT
// Categories (semantics §13) as bits, once per native call: #:category and
// #:collides-with name categories with symbols; the core compares bits.
// A table lives on the stack of one call and is shared by every list the
// call decodes (a scene and the entity detected against it), so the same
// name is the same bit throughout. It keeps no SCM: a symbol is known by its
// bits, and the plists being decoded keep every symbol alive until the
// call returns.
#pragma once
#include <libguile.h>

#include <cstdint>

#include "body.hpp"
#include "constants.hpp"
#include "failure.hpp"

namespace ds::guile {

// An entity's category names by identity (a symbol's SCM bits), so that a
// cached entity gets its bits again each call without walking its plist.
// The cached plist, which the batch's cache vector keeps alive, holds the
// symbols: the identities stay unique while they are kept.
struct CategoryNames {
    static constexpr int kInline = 8;  // longer #:collides-with lists are read from the plist
    static constexpr int8_t kAbsent = -1, kLong = -2;
    uint64_t category = 0;     // 0: no #:category
    int8_t count = kAbsent;    // names below, or kAbsent (no list) or kLong
    uint64_t names[kInline];

    // From decoding's values (Decoded::category, ::collides_with; checked).
    static CategoryNames of(SCM category, SCM collides_with);
};

class CategoryTable {
public:
    CategoryTable();

    // Sets b's category bit and collides-with mask from the values decoding
    // kept (SCM_UNDEFINED when absent; both already checked). Fails, naming
    // the key and the name, at the 65th category of the call.
    bool assign(SCM category, SCM collides_with, Body& b, Failure& f);
    // The same from the names a cache kept; `entity` is read only for a
    // list too long to keep.
    bool assign(const CategoryNames& names, SCM entity, Body& b, Failure& f);

private:
    // Both assigns: the names, and the #:collides-with list itself when it
    // is too long for them (CategoryNames::kLong).
    bool assign_from(const CategoryNames& names, SCM long_list, Body& b, Failure& f);
    bool index_of(SCM key, uint64_t name, uint8_t& index, Failure& f);
    bool mask_of(SCM list, uint64_t& mask, Failure& f);
    uint64_t names_[kMaxCategories];  // a symbol's SCM bits, by bit index; 0 is 'default
    int count_ = 0;
};

static_assert(survives_longjmp<CategoryTable, CategoryNames>);

}  // namespace ds::guile
