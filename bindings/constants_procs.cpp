// SPDX-License-Identifier: MIT
// The core's rule constants as Scheme variables of (downstroke native), so
// (downstroke physics) and the engine read them instead of repeating them.
#include <cstdint>

#include "constants.hpp"
#include "registry.hpp"
#include "tween_step.hpp"

namespace ds::guile {

namespace {

// Scheme sees these as exact integers (*gravity* is 1, not 1.0). consteval,
// not a double template parameter, which clang before 18 cannot take: a
// constant that is not an integer still fails to compile (the throw).
consteval int64_t exact_integer(double v) {
    if (static_cast<double>(static_cast<int64_t>(v)) != v) throw "a rule constant Scheme sees must be an integer";
    return static_cast<int64_t>(v);
}

void define_constant(const char* name, SCM value) {
    scm_c_define(name, value);
    scm_c_export(name, nullptr);
}

}  // namespace

void register_constants() {
    define_constant("%gravity", scm_from_int64(exact_integer(kGravity)));
    define_constant("%jump-force", scm_from_int64(exact_integer(kJumpForce)));
    define_constant("%on-solid-tolerance", scm_from_int64(exact_integer(kOnSolidTolerance)));
    define_constant("%max-substeps", scm_from_int64(exact_integer(kMaxSubsteps)));
    define_constant("%max-tween-repeat", scm_from_int64(exact_integer(kMaxTweenRepeat)));
    define_constant("%max-tween-props", scm_from_int64(exact_integer(kMaxTweenProps)));
}

}  // namespace ds::guile
