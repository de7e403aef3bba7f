// Categories (semantics §13) as bits, once per native call: #:category and
// #:collides-with name categories with symbols; the core compares bits.
// A table lives on the stack of one call and is shared by every list the
// call decodes (a scene and the entity detected against it), so the same
// name is the same bit throughout. It keeps no SCM: a symbol is known by its
// address, and the plists being decoded keep every symbol alive until the
// call returns.
#pragma once
#include <libguile.h>

#include <cstdint>

#include "body.hpp"
#include "constants.hpp"
#include "failure.hpp"

namespace ds::guile {

class CategoryTable {
public:
    CategoryTable();

    // Sets b's category bit and collides-with mask from the values decoding
    // kept (Decoded::category, Decoded::collides_with: SCM_UNDEFINED when
    // absent; both already checked). Fails, naming the key and the name,
    // at the 65th category of the call.
    bool assign(SCM category, SCM collides_with, Body& b, Failure& f);

private:
    bool bit_of(SCM key, SCM name, uint64_t& bit, Failure& f);
    uint64_t names_[kMaxCategories];  // a symbol's SCM bits, by bit index; 0 is 'default
    int count_ = 0;
};

static_assert(survives_longjmp<CategoryTable>);

}  // namespace ds::guile
