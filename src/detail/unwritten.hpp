// SPDX-License-Identifier: MIT
// What the Scheme bindings store in a report member (#:blocked, #:touching,
// #:standing-on; semantics §10) for a plist that lacks the key or holds a
// value the bindings compare themselves. Private: a C++ body always has its
// report members, and the steps overwrite whatever these marks are, so a
// frame reports the member changed exactly when the plist needs writing.
#pragma once
#include <cstdint>

#include "../body.hpp"

namespace ds {

// Body::blocked holds no side list in canonical form (absent, or anything
// else): the next write must reach it even when it names no side. Outside
// kSidesAll, which a tile step keeps of what it found.
constexpr uint8_t kSidesUnwritten = 1u << 7;
static_assert((kSidesUnwritten & kSidesAll) == 0);
// Body::touching before push-apart has marked it (the plist lacks the key).
constexpr uint8_t kReportUnwritten = 1;
// Body::standing_on as decoded: the plist lacks the key, or holds a name
// the bindings compare with the new one.
constexpr int32_t kStandingAbsent = -1;
constexpr int32_t kStandingUnknown = -2;

}  // namespace ds
