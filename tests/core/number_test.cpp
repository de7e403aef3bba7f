// SPDX-License-Identifier: MIT
// ds::Num: a double plus whether it is an exact integer (semantics §1).
#include <cmath>

#include "number.hpp"
#include "support.hpp"

using namespace dst;
using ds::Num;

TEST_SUITE("number") {

TEST_CASE("a default Num is exact zero") {
    Num n;
    CHECK(n.v == 0.0);
    CHECK(n.exact);
    CHECK_FALSE(std::signbit(n.v));
}

TEST_CASE("integer() and flonum() set the provenance bit") {
    CHECK_EXACT(Num::integer(103), 103);
    CHECK_FLONUM(Num::flonum(103), 103);
    CHECK_EXACT(Num::integer(-7), -7);
    CHECK_FLONUM(Num::flonum(1.5), 1.5);
}

TEST_CASE("sums and differences are exact only when both operands are") {
    CHECK_EXACT(I(100) + I(3), 103);
    CHECK_FLONUM(I(100) + F(1.5), 101.5);
    CHECK_FLONUM(F(100) + I(3), 103);  // 103.0, not 103
    CHECK_FLONUM(F(0.5) + F(0.25), 0.75);
    CHECK_EXACT(I(10) - I(16), -6);
    CHECK_FLONUM(I(10) - F(16), -6);
    CHECK_FLONUM(F(10) - I(16), -6);
    // exact zero does not launder a flonum, nor does a flonum zero stay out of an exact sum
    CHECK_FLONUM(F(5) + I(0), 5);
    CHECK_FLONUM(I(5) + F(0), 5);
}

TEST_CASE("sums stay exact for integers up to 2^53") {
    CHECK(ds::kMaxExact == 9007199254740992.0);
    CHECK_EXACT(I(1e9) + I(1), 1000000001.0);
    CHECK_EXACT(I(ds::kMaxExact - 2) + I(1), ds::kMaxExact - 1);
    CHECK_FLONUM(F(1e12) + F(0.5), 1000000000000.5);
}

TEST_CASE("same compares value, exactness and the sign of a flonum zero") {
    CHECK(ds::same(I(5), I(5)));
    CHECK(ds::same(F(5), F(5)));
    CHECK(ds::same(F(-2.5), F(-2.5)));
    CHECK_FALSE(ds::same(I(5), F(5)));
    CHECK_FALSE(ds::same(F(5), I(5)));
    CHECK_FALSE(ds::same(I(5), I(6)));
    CHECK_FALSE(ds::same(F(0.0), F(-0.0)));
    CHECK_FALSE(ds::same(F(-0.0), F(0.0)));
    CHECK(ds::same(F(-0.0), F(-0.0)));
    CHECK_FALSE(ds::same(I(0), F(0.0)));
    CHECK(ds::same(I(0), I(0)));
}

}  // TEST_SUITE
