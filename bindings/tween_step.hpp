// SPDX-License-Identifier: MIT
// Advancing an entity's #:tween: shared by step-tweens and the frame.
#pragma once
#include <libguile.h>

#include <cstddef>
#include <cstdint>

#include "failure.hpp"

namespace ds::guile {

// Props a tween may drive; make-tween refuses more.
constexpr size_t kMaxTweenProps = 32;

// The most extra cycles make-tween accepts (Scheme sees it as
// %max-tween-repeat): the core counts cycles in doubles, which are exact
// only up to 2^53, and at 1 ms a cycle that is 285 000 years of play.
constexpr int64_t kMaxTweenRepeat = (int64_t{1} << 53) - 1;

// The entity after its tween advanced by dt ms (on-complete applied when the
// tween ends). Calls Scheme for a custom easing and for on-complete, so the
// caller must own no C++ resources across it. dt must be finite.
SCM advance_entity_tween(SCM entity, double dt, Failure& f);

}  // namespace ds::guile
