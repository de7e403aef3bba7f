// Native walks over Scheme lists that cannot hang on a circular one.
// Brent's variant of Floyd's tortoise and hare: the walk itself is the
// hare, and the tortoise waits on a cell the hare passed, moving up to it
// after waits of 2, 4, 8, … steps (at x₀, x₂, x₆, x₁₄, …, the head being
// x₀). On a list that ends every cell is new, so the hare never lands on the
// tortoise. On a circular one (μ cells before a cycle of λ) it does once the
// tortoise sits in the cycle and waits at least λ steps: within
// 3·(μ + λ) + 4 steps. Unlike Floyd's, the tortoise never walks by itself
// (no second cdr, no unchecked cell): one comparison and one count a step.
#pragma once
#include <libguile.h>

#include <cstdint>

#include "failure.hpp"

namespace ds::guile {

class Tortoise {
public:
    // Call with every cell of the walk in order, the head first. True when
    // the hare has come back to the tortoise's cell: the list is circular.
    bool caught(SCM hare) {
        if (scm_is_eq(hare, at_)) [[unlikely]]
            return true;
        ++steps_;
        if ((steps_ & (steps_ + 1)) == 0) at_ = hare;  // after 1, 3, 7, 15, … calls
        return false;
    }

private:
    SCM at_ = SCM_UNDEFINED;  // no pair; on the stack, which the collector scans
    uint64_t steps_ = 0;      // calls so far
};

static_assert(survives_longjmp<Tortoise>);

// Records "<what>: expected <expected>, got a circular list ~S" (irritant
// list; Guile's printer marks the cycle instead of looping).
void fail_circular(Failure& f, const char* what, const char* expected, SCM list);

}  // namespace ds::guile
