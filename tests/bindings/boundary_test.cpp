// SPDX-License-Identifier: MIT
// The native procedures' boundary: what a C++ exception escaping one
// becomes, and what the registration refuses.
#include <doctest/doctest.h>
#include <libguile.h>

#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "registry.hpp"

namespace {

using namespace ds::guile;

int destroyed = 0;
struct Probe {
    ~Probe() { ++destroyed; }
};

SCM throws_bad_alloc(SCM) {
    Probe p;
    throw std::bad_alloc();
}
SCM throws_runtime_error(SCM, SCM) {
    Probe p;
    std::vector<int> owned(100);
    throw std::runtime_error("no ~ such thing");
}
SCM throws_int() { throw 42; }
SCM identity(SCM x) { return x; }

void define_test_module(void*) {
    define_procedure<1, 0, 0, throws_bad_alloc>("throws-bad-alloc", "Throws std::bad_alloc.");
    define_procedure<1, 0, 1, throws_runtime_error>("throws-runtime-error", "Throws std::runtime_error.");
    define_procedure<0, 0, 0, throws_int>("throws-int", "Throws an int.");
    define_procedure<1, 0, 0, identity>("identity", "Its argument.");
}

// Evaluates EXPR in a module using the test procedures; errors come back as
// the printed (key . message) of the error.
std::string eval(const char* expr) {
    static bool defined = false;
    if (!defined) {
        scm_c_define_module("boundary-test", define_test_module, nullptr);
        defined = true;
    }
    const std::string program =
        std::string("(begin (use-modules (boundary-test)) "
                    "(catch #t (lambda () (object->string ") + expr +
        "))  (lambda (key subr message args rest)"
        "   (format #f \"~a: In procedure ~a: ~a\" key subr (apply format #f message args)))))";
    char* text = scm_to_utf8_string(scm_c_eval_string(program.c_str()));
    std::string out = text;
    free(text);
    return out;
}

}  // namespace

TEST_SUITE("boundary") {
    TEST_CASE("a C++ exception escaping a native procedure is a Scheme error naming it") {
        destroyed = 0;
        CHECK(eval("(throws-bad-alloc 1)") == "misc-error: In procedure throws-bad-alloc: std::bad_alloc");
        CHECK(destroyed == 1);  // unwound as C++, before the Scheme error was raised
        CHECK(eval("(throws-runtime-error 1 2 3)") ==
              "misc-error: In procedure throws-runtime-error: no ~ such thing");
        CHECK(destroyed == 2);
        CHECK(eval("(throws-int)") == "misc-error: In procedure throws-int: unknown C++ failure");
    }

    TEST_CASE("after one, native procedures and Scheme errors work as before") {
        CHECK(eval("(throws-bad-alloc 1)").starts_with("misc-error"));
        CHECK(eval("(identity 'still-here)") == "still-here");
        CHECK(eval("(identity)").starts_with("wrong-number-of-args"));
        CHECK(eval("(procedure-documentation identity)") == "\"Its argument.\"");
    }
}
