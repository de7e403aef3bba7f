// The core's rule constants as Scheme variables of (downstroke native), so
// (downstroke physics) and the engine read them instead of repeating them.
#include <cstdint>

#include "constants.hpp"
#include "registry.hpp"
#include "tween_step.hpp"

namespace ds::guile {

namespace {

// Scheme sees these as exact integers (*gravity* is 1, not 1.0).
template <auto V>
SCM exact() {
    static_assert(static_cast<double>(static_cast<int64_t>(V)) == static_cast<double>(V),
                  "a rule constant Scheme sees must be an integer");
    return scm_from_int64(static_cast<int64_t>(V));
}

void define_constant(const char* name, SCM value) {
    scm_c_define(name, value);
    scm_c_export(name, nullptr);
}

}  // namespace

void register_constants() {
    define_constant("%gravity", exact<kGravity>());
    define_constant("%jump-force", exact<kJumpForce>());
    define_constant("%on-solid-tolerance", exact<kOnSolidTolerance>());
    define_constant("%max-substeps", exact<kMaxSubsteps>());
    define_constant("%max-tween-repeat", exact<kMaxTweenRepeat>());
    define_constant("%max-tween-props", exact<kMaxTweenProps>());
}

}  // namespace ds::guile
