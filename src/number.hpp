// SPDX-License-Identifier: MIT
// A game-sized real number with one bit of provenance: whether it is an exact
// integer. Scheme keeps 103 and 103.0 apart, so the core must too (semantics §1):
// a result is exact only when everything it was computed from was exact.
#pragma once
#include <cmath>
#include <cstdint>

namespace ds {

struct Num {
    double v = 0.0;
    bool exact = true;

    static constexpr Num integer(double value) { return {value, true}; }
    static constexpr Num flonum(double value) { return {value, false}; }
};

inline Num operator+(Num a, Num b) { return {a.v + b.v, a.exact && b.exact}; }
inline Num operator-(Num a, Num b) { return {a.v - b.v, a.exact && b.exact}; }
inline Num operator*(Num a, Num b) { return {a.v * b.v, a.exact && b.exact}; }
inline Num operator-(Num a) { return {-a.v, a.exact}; }

// Same value and same exactness, and for flonums the same sign of zero:
// Scheme's eqv? tells 0.0 from -0.0, so writing one over the other is a change (semantics §1).
inline bool same(Num a, Num b) {
    return a.exact == b.exact && a.v == b.v && std::signbit(a.v) == std::signbit(b.v);
}

// Integers the core may carry as exact: doubles represent them without loss.
constexpr double kMaxExact = 9007199254740992.0;  // 2^53

}  // namespace ds
