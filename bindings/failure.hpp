// Errors raised at the boundary. A Guile error longjmps over C++ frames, so a
// native procedure records what went wrong in a Failure (no destructor to
// skip: a fixed buffer and SCM values on the stack, which the collector
// scans), lets every C++ object die, and only then calls raise().
#pragma once
#include <libguile.h>

#include <cstdarg>
#include <exception>

namespace ds::guile {

struct Failure {
    const char* proc = nullptr;  // the Scheme procedure's name
    const char* key = "wrong-type-arg";  // the Scheme error key
    char message[256] = {0};     // a format string for scm_error: ~S takes an irritant
    SCM irritants = SCM_EOL;
    bool failed = false;

    explicit operator bool() const { return failed; }
};

// Records a failure; `irritants` are SCM values for the message's ~S slots
// (up to four, SCM_UNDEFINED-terminated by the helpers below).
void fail(Failure& f, const char* key, SCM irritants, const char* fmt, ...)
    __attribute__((format(printf, 4, 5)));

// Records a failure whose message is "<what>: <text>" (just text when what
// is null) taken literally (a ~
// in text, as in a home-directory path, is not a format directive).
void fail_text(Failure& f, const char* key, const char* what, const char* text);

// Raises the recorded failure as a Scheme error. Call it only once nothing
// on the C++ stack between here and Guile owns a resource.
[[noreturn]] void raise(const Failure& f);

// Runs fn (a C++ callable that may throw) and turns any exception into a
// Failure, so nothing escapes into Guile.
template <typename Fn>
bool guarded(Failure& f, const char* what, Fn&& fn) noexcept {
    try {
        fn();
        return true;
    } catch (const std::exception& e) {
        fail_text(f, "misc-error", what, e.what());
    } catch (...) {
        fail_text(f, "misc-error", what, "unknown C++ failure");
    }
    return false;
}

}  // namespace ds::guile
