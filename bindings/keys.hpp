// The keywords and symbols the bindings compare against, interned once after
// Guile has started (never in namespace-scope statics: interning needs a
// running Guile). Each is protected from the collector when interned, since
// nothing else may hold on to it.
#pragma once
#include <libguile.h>

#include <cstdint>

namespace ds::guile {

// The physics keys of an entity plist, in the order decode tests them.
enum PhysKey : uint8_t {
    kX, kY, kWidth, kHeight, kVx, kVy, kAy,
    kGravity, kOnGround, kSolid, kImmovable,
    kSkipPipelines, kTween, kId, kGroupId, kGroupOrigin, kGroupLocalX, kGroupLocalY,
    kPhysKeyCount,
    kNotPhysics = 0xff,
};

struct Keys {
    SCM key[kPhysKeyCount];
    SCM skip_symbol[9];  // by bit index of ds::Skip
    SCM swept, discrete;

    // Which physics key a keyword is, or kNotPhysics.
    uint8_t lookup(SCM keyword) const;
};

// Valid after init_keys().
extern const Keys* keys;
void init_keys();

const char* key_name(uint8_t k);  // "x", "gravity?", … without the #:

}  // namespace ds::guile
