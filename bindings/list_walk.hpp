// SPDX-License-Identifier: MIT
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

#include <cstddef>
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

// How far a hot walk may go before it asks circular() once: ordinary
// plists and #:skip-pipelines lists are far shorter, so they never pay even
// for a tortoise (the plist walk is bound by memory latency, where any state
// carried in the loop showed), and a circular list always gets there.
constexpr size_t kStepsBeforeCycleCheck = 64;

// Whether a list (Stride 1) or a plist walked key by key (Stride 2) is
// circular: one walk with a Tortoise, out of line as hot walks seldom call it.
template <int Stride>
[[gnu::cold, gnu::noinline]] bool circular(SCM list) {
    Tortoise tortoise;
    for (SCM p = list; scm_is_pair(p); p = SCM_CDR(p)) {
        if (tortoise.caught(p)) return true;
        if constexpr (Stride == 2) {
            p = SCM_CDR(p);
            if (!scm_is_pair(p)) return false;
        }
    }
    return false;
}

// Records "<what>: expected <expected>, got a circular list ~S" (irritant
// list; Guile's printer marks the cycle instead of looping).
void fail_circular(Failure& f, const char* what, const char* expected, SCM list);

}  // namespace ds::guile
