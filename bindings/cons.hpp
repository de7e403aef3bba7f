// SPDX-License-Identifier: MIT
// Pairs allocated from the current thread's own free lists, as the VM does:
// scm_cons goes through the collector's general entry point every time, and
// a frame of a falling crowd conses a few hundred thousand pairs.
#pragma once
#include <libguile.h>
// gc-inline.h is C: its volatile compound assignments warn in GCC's C++20
// (clang has no such warning group, and would warn about the pragma).
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wvolatile"
#endif
#include <libguile/gc-inline.h>

namespace ds::guile {

struct Conser {
    scm_thread* thread = SCM_I_THREAD_DATA(scm_current_thread());
    SCM operator()(SCM car, SCM cdr) const { return scm_inline_cons(thread, car, cdr); }
};

}  // namespace ds::guile
#pragma GCC diagnostic pop
