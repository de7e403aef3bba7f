// SPDX-License-Identifier: MIT
// Errors raised at the boundary. A Guile error longjmps over C++ frames, so a
// native procedure records what went wrong in a Failure (no destructor to
// skip: a pointer to collected memory and SCM values on the stack, which the
// collector scans), lets every C++ object die, and only then calls raise().
#pragma once
#include <libguile.h>

#include <cstdarg>
#include <exception>
#include <type_traits>

namespace ds::guile {

struct Failure {
    const char* proc = nullptr;  // the Scheme procedure's name
    const char* key = "wrong-type-arg";  // the Scheme error key
    SCM irritants = SCM_EOL;
    bool failed = false;
    // A format string for scm_error (~S takes an irritant), written by fail()
    // or fail_text(): whole, however long (a reason cut short is a reason
    // lost), in pointerless memory the collector frees once no stack holds it.
    const char* message = nullptr;

    explicit Failure(const char* proc_name = nullptr) : proc(proc_name) {}
    explicit operator bool() const { return failed; }
};

// Whether objects of these types may be alive in a C++ frame that a Guile
// non-local exit longjmps over (an error raised by a libguile call, or by
// Scheme code the frame calls back: a custom easing, an on-complete, and
// what they call): only when there is no destructor for the jump to skip.
// References own nothing and qualify.
template <class... T>
inline constexpr bool survives_longjmp = (std::is_trivially_destructible_v<T> && ...);

static_assert(survives_longjmp<Failure>, "every native procedure keeps a Failure across Guile calls");

// Records a failure; `irritants` are SCM values for the message's ~S slots
// (up to four, SCM_UNDEFINED-terminated by the helpers below). Both allocate
// from the collector: call them outside a C++ catch handler, which a Guile
// out-of-memory error would longjmp out of.
void fail(Failure& f, const char* key, SCM irritants, const char* fmt, ...)
    __attribute__((format(printf, 4, 5)));

// Records a failure whose message is "<what>: <text>" (just text when what
// is null) taken literally (a ~
// in text, as in a home-directory path, is not a format directive).
void fail_text(Failure& f, const char* key, const char* what, const char* text);

// A malloc'd copy of the exception being handled's what(), or null when
// there is no memory for one: what a catch handler keeps for fail_text to
// read after the handler has ended. The caller frees it.
char* copy_of_handled_reason() noexcept;

// Raises the recorded failure as a Scheme error. Call it only once nothing
// on the C++ stack between here and Guile owns a resource.
[[noreturn]] void raise(const Failure& f);

// Runs fn (a C++ callable that may throw) and turns any exception into a
// Failure, so nothing escapes into Guile. fn may call libguile, and Scheme,
// whose errors longjmp out of it: its closure (captures by reference) must
// have no destructor to skip.
template <typename Fn>
bool guarded(Failure& f, const char* what, Fn&& fn) noexcept {
    static_assert(survives_longjmp<std::remove_reference_t<Fn>>,
                  "a Guile error can longjmp out of a guarded closure: capture by reference");
    char* reason = nullptr;
    try {
        fn();
        return true;
    } catch (...) {
        reason = copy_of_handled_reason();
    }
    // fail_text allocates from the collector, whose out-of-memory error
    // longjmps: the dynwind frees the reason on that way out too.
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    if (reason) scm_dynwind_free(reason);
    fail_text(f, "misc-error", what, reason ? reason : "unknown C++ failure (no memory to copy its text)");
    scm_dynwind_end();
    return false;
}

}  // namespace ds::guile
