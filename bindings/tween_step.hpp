// Advancing an entity's #:tween: shared by step-tweens and the frame.
#pragma once
#include <libguile.h>

#include "failure.hpp"

namespace ds::guile {

// Props a tween may drive; make-tween refuses more.
constexpr size_t kMaxTweenProps = 32;

// The entity after its tween advanced by dt ms (on-complete applied when the
// tween ends). Calls Scheme for a custom easing and for on-complete, so the
// caller must own no C++ resources across it. dt must be finite.
SCM advance_entity_tween(SCM entity, double dt, Failure& f);

}  // namespace ds::guile
