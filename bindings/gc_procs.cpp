// SPDX-License-Identifier: MIT
// How often the collector runs: Boehm's free-space divisor, and the default
// the engine picks for it. Each collection marks every live object (a scene
// of 10k entities is ~4 MB of plists), while a frame of such a scene
// allocates about 1 MB of fresh plist heads. Boehm's default (3) collects
// after allocating a third of twice the live heap; 1 lets three times as
// much go by, which at 10k entities halves the time spent collecting
// (docs/engine.org has the figures) for about 13 MB more heap.
#include <gc/gc.h>

#include <cstdlib>

#include "failure.hpp"
#include "gc_clock.hpp"
#include "registry.hpp"

namespace ds::guile {

namespace {

constexpr long kMaxDivisor = 1000;  // beyond this the collector runs after every few objects

SCM gc_space_divisor() { return scm_from_ulong(GC_get_free_space_divisor()); }

SCM set_gc_space_divisor(SCM n) {
    Failure f{"set-gc-space-divisor!"};
    if (!scm_is_exact_integer(n))
        fail(f, "wrong-type-arg", scm_list_1(n), "expected an exact integer (the free-space divisor), got ~S");
    else if (!scm_is_signed_integer(n, 1, kMaxDivisor))
        fail(f, "out-of-range", scm_list_1(n), "the free-space divisor must be from 1 to 1000, got ~S");
    if (f) raise(f);
    GC_set_free_space_divisor(static_cast<GC_word>(scm_to_long(n)));
    return SCM_UNSPECIFIED;
}

// The collections since the library loaded and the wall-clock time they
// took (gc_clock.hpp says why not Guile's gc-time-taken).
SCM gc_clock() {
    const GcReading r = gc_reading();
    return scm_cons(scm_from_uint64(r.collections), scm_from_uint64(r.ns));
}

}  // namespace

void apply_gc_policy() {
    start_gc_clock();
    // A divisor the user chose in the environment (Boehm read it at start) wins.
    const char* chosen = std::getenv("GC_FREE_SPACE_DIVISOR");
    if (chosen == nullptr || *chosen == '\0') GC_set_free_space_divisor(1);
}

void register_gc_procedures() {
    define_procedure<0, 0, 0, gc_space_divisor>("%gc-space-divisor",
        WrapperDoc{"()", "gc-space-divisor", "(downstroke engine)"});
    define_procedure<0, 0, 0, gc_clock>("%gc-clock",
        "() → (collections . ns): the collections since Downstroke loaded and the wall-clock time\n"
        "they took in nanoseconds (Guile's gc-time-taken is process CPU time, which counts every\n"
        "marking thread).");
    define_procedure<1, 0, 0, set_gc_space_divisor>("%set-gc-space-divisor!",
        WrapperDoc{"(n)", "set-gc-space-divisor!", "(downstroke engine)"});
}

}  // namespace ds::guile
