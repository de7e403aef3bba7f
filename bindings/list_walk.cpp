// SPDX-License-Identifier: MIT
#include "list_walk.hpp"

namespace ds::guile {

void fail_circular(Failure& f, const char* what, const char* expected, SCM list) {
    fail(f, "wrong-type-arg", scm_list_1(list), "%s: expected %s, got a circular list ~S", what, expected);
}

}  // namespace ds::guile
