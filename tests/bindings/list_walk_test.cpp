// SPDX-License-Identifier: MIT
// The Tortoise and circular() of list_walk.hpp: never a false alarm on a list that ends,
// and a circular one caught within the bound its header promises.
#include <doctest/doctest.h>
#include <libguile.h>

#include <cstdint>

#include "list_walk.hpp"

namespace {

using ds::guile::Tortoise;

// mu cells, then a cycle of lambda cells (lambda 0: a proper list of mu).
SCM lasso(int mu, int lambda) {
    SCM cycle = SCM_EOL, last = SCM_BOOL_F;
    for (int i = 0; i < lambda; ++i) {
        cycle = scm_cons(scm_from_int(i), cycle);
        if (i == 0) last = cycle;
    }
    if (lambda > 0) scm_set_cdr_x(last, cycle);
    SCM list = cycle;
    for (int i = 0; i < mu; ++i) list = scm_cons(scm_from_int(-i), list);
    return list;
}

// Steps until the tortoise is caught, or -1 when the walk ends first.
int64_t steps_to_catch(SCM list, int64_t limit) {
    Tortoise tortoise;
    int64_t n = 0;
    for (SCM p = list; scm_is_pair(p) && n < limit; p = SCM_CDR(p), ++n)
        if (tortoise.caught(p)) return n;
    return -1;
}

}  // namespace

TEST_SUITE("list-walk") {
    TEST_CASE("a proper list is never taken for a circular one") {
        for (int n = 0; n <= 300; ++n) CHECK(steps_to_catch(lasso(n, 0), 1000) == -1);
    }
    TEST_CASE("a circular list is caught within 3(mu + lambda) + 4 steps") {
        for (int mu = 0; mu <= 40; ++mu)
            for (int lambda = 1; lambda <= 40; ++lambda) {
                const int64_t bound = 3 * (mu + lambda) + 4;
                const int64_t n = steps_to_catch(lasso(mu, lambda), 10 * bound);
                CAPTURE(mu);
                CAPTURE(lambda);
                CHECK(n >= mu + lambda);  // the hare must have gone round once
                CHECK(n <= bound);
            }
    }
    TEST_CASE("circular<1> and circular<2> tell lassos from lists, whatever the cycle's parity") {
        for (int mu = 0; mu <= 9; ++mu)
            for (int lambda = 0; lambda <= 9; ++lambda) {
                CAPTURE(mu);
                CAPTURE(lambda);
                CHECK(ds::guile::circular<1>(lasso(mu, lambda)) == (lambda > 0));
                CHECK(ds::guile::circular<2>(lasso(mu, lambda)) == (lambda > 0));
            }
    }
}
