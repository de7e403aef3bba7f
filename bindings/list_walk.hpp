// Native walks over Scheme lists that cannot hang on a circular one.
// Floyd's tortoise and hare: the walk itself is the hare, and a Tortoise
// follows it at half speed. On a list that ends, the hare is always ahead
// of the tortoise; on a circular one, both end up going round the cycle and
// the hare, gaining one step every second step, lands on the tortoise
// within (cells before the cycle + cycle length) steps of the tortoise.
// The cost is one comparison (and every second step one cdr) per step.
#pragma once
#include <libguile.h>

#include <cstdint>

#include "failure.hpp"

namespace ds::guile {

// Stride: the cells one step of the walk moves: 1 for a list, 2 for a plist
// walked key by key.
template <int Stride>
class Tortoise {
    static_assert(Stride == 1 || Stride == 2);

public:
    explicit Tortoise(SCM head) : at_(head) {}

    // Call with every cell the walk reaches, the head included (x₀, x₁, …,
    // each x a pair the walk has checked). True when the list is circular:
    // at step i (even, ≥ 2) the tortoise is at x_{i/2}, and x_{i/2} = x_i
    // happens exactly when the cells repeat. It only steps on cells the hare
    // has already checked.
    bool caught(SCM hare) {
        const uint64_t i = steps_++;
        if (i == 0 || (i & 1) != 0) return false;
        at_ = Stride == 1 ? SCM_CDR(at_) : SCM_CDR(SCM_CDR(at_));
        return scm_is_eq(at_, hare);
    }

private:
    SCM at_;  // on the stack, which the collector scans
    uint64_t steps_ = 0;
};

static_assert(survives_longjmp<Tortoise<1>, Tortoise<2>>);

// Records "<what>: expected <expected>, got a circular list ~S" (irritant
// list; Guile's printer marks the cycle instead of looping).
void fail_circular(Failure& f, const char* what, const char* expected, SCM list);

}  // namespace ds::guile
