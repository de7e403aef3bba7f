// SPDX-License-Identifier: MIT
// The physics view of one entity: plain data, decoded once from a plist and
// compared field by field afterwards to find what a frame changed.
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>

#include "number.hpp"
#include "export.hpp"

namespace ds {

// The seed's skip symbols (#:skip-pipelines), one bit each.
enum Skip : uint16_t {
    kSkipAcceleration = 1u << 0,
    kSkipGravity = 1u << 1,
    kSkipVelocityX = 1u << 2,
    kSkipVelocityY = 1u << 3,
    kSkipTileX = 1u << 4,
    kSkipTileY = 1u << 5,
    kSkipOnSolid = 1u << 6,
    kSkipEntityCollisions = 1u << 7,
    kSkipTweens = 1u << 8,
    kSkipCarry = 1u << 9,  // not carried by a carrier (semantics §11)
    kSkipSpeedLimits = 1u << 10,  // no #:drag or #:max-vx/#:max-vy (semantics §14)
};
constexpr int kSkipCount = 11;  // the Skip bits above

// Returns the bit for a skip symbol's name, or 0 for a name physics does not know.
DOWNSTROKE_API uint16_t skip_bit(const char* name);
// The symbol name of one skip bit (for messages and stats).
DOWNSTROKE_API const char* skip_name(uint16_t bit);

// Fields a step may write (the DS_FIELD rows of body_fields.def); a frame
// reports the changed ones as a mask of these. The bit order is the order a
// step writes several keys in (x y width height vx vy ay group-local-x
// group-local-y on-ground?).
enum FieldBit : int {
#define DS_FIELD(Name, type, member, keyword, rule) kFieldBit##Name,
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
    kFieldBitCount,
};
enum Field : uint32_t {
#define DS_FIELD(Name, type, member, keyword, rule) kField##Name = 1u << kFieldBit##Name,
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
};
constexpr int kFieldCount = kFieldBitCount;

// The sides of #:blocked (semantics §10), in the order the list names them.
enum Side : uint8_t {
    kSideLeft = 1u << 0,
    kSideRight = 1u << 1,
    kSideUp = 1u << 2,
    kSideDown = 1u << 3,
    kSidesX = kSideLeft | kSideRight,
    kSidesY = kSideUp | kSideDown,
    kSidesAll = kSidesX | kSidesY,
};
// Body::contacts, what #:contacts? asks for (semantics §10): no report, the
// report with #:touching a list of names, or of (name . side) pairs. Truthy
// exactly when the body reports.
enum ContactReport : uint8_t { kContactsOff = 0, kContactsNames = 1, kContactsSides = 2 };

// Categories (semantics §13) as bits of the table a caller builds for one
// frame: bit 0 is 'default, the category of a body that names none. A body
// that names no #:collides-with collides with every category.
struct CategoryBit {
    uint8_t index = 0;  // the bit's index, 0–63 (kMaxCategories)
    uint64_t bits() const { return uint64_t{1} << index; }
    bool operator==(const CategoryBit&) const = default;
};
struct CategoryMask {
    uint64_t bits = ~uint64_t{0};
    bool operator==(const CategoryMask&) const = default;
};

// A number from 0 to 1 (#:bounce) in 8 bytes: its exactness is kept in the
// sign bit, which such a number does not use otherwise (an exact value is
// stored negated). Zero reads as exact either way.
struct UnitNum {
    double code = 0.0;
    double value() const { return std::fabs(code); }
    bool exact() const { return std::signbit(code) || code == 0; }
    Num num() const { return {value(), exact()}; }
    static UnitNum of(Num n) { return {n.exact ? -n.v : n.v}; }
    bool operator==(const UnitNum& o) const { return std::bit_cast<uint64_t>(code) == std::bit_cast<uint64_t>(o.code); }
};

// A non-negative number (#:max-vx, #:max-vy, #:drag; semantics §14) in 8
// bytes, its exactness in the sign bit as UnitNum keeps it. What a body
// without the key holds: no speed limit is +∞ (`UnlimitedWhenAbsent`; a
// value no plist can give, infinities being refused), no drag is 0.
template <bool UnlimitedWhenAbsent>
struct NonNegNum {
    static constexpr double kAbsent = UnlimitedWhenAbsent ? HUGE_VAL : 0.0;
    double code = kAbsent;
    double value() const { return std::fabs(code); }
    bool exact() const { return std::signbit(code) || code == 0; }
    bool absent() const { return code == kAbsent; }
    Num num() const { return {value(), exact()}; }
    static NonNegNum of(Num n) { return {n.exact ? -n.v : n.v}; }
    bool operator==(const NonNegNum& o) const { return std::bit_cast<uint64_t>(code) == std::bit_cast<uint64_t>(o.code); }
};
using SpeedCap = NonNegNum<true>;
using DragNum = NonNegNum<false>;

// #:gravity-scale (semantics §14): any finite real, 1 when absent.
struct GravityScale {
    Num n = Num::integer(1);
    bool absent() const { return n.exact && n.v == 1; }
};

struct Body {
    // One member per row of body_fields.def, in its order: x y w h (Num: the
    // box is [x, x+w) × [y, y+h)), vx vy ay, local_x local_y, the flags
    // gravity on_ground solid immovable group_origin, skip (Skip bits), and
    // the identity tags id and group (0: absent, or #f for the group).
#define DS_FIELD(Name, type, member, keyword, rule) type member{};
#define DS_KEY(Name, type, member, keyword, rule) type member{};
#include "body_fields.def"

    bool skips(uint16_t bit) const { return (skip & bit) != 0; }
    // Solid, not a sensor and not a ghost: takes part in push-apart and can
    // hold others up.
    bool collides() const { return solid && !sensor && !skips(kSkipEntityCollisions); }
    // A sensor that is not a ghost: reports the bodies it overlaps (§13).
    bool senses() const { return sensor && !skips(kSkipEntityCollisions); }
    // Its pairs are kept in the scene's contacts (§10, §13).
    bool reports_pairs() const { return contacts || sensor; }
    // What detect-on-solid looks at: it applies to this body.
    bool detects_ground() const { return gravity && !skips(kSkipOnSolid); }
    // Has a speed limit or a drag (semantics §14): apply_speed_limits has work.
    bool limits_speed() const { return !(drag.absent() && max_vx.absent() && max_vy.absent()); }
};

// Whether two bodies' categories let them meet (semantics §13): each one's
// #:collides-with names the other's category (Box2D's rule, as bits).
inline bool categories_meet(uint64_t a_category, uint64_t a_mask, uint64_t b_category, uint64_t b_mask) {
    return (a_mask & b_category) != 0 && (b_mask & a_category) != 0;
}
inline bool categories_meet(const Body& a, const Body& b) {
    return categories_meet(a.category.bits(), a.collides_with.bits, b.category.bits(), b.collides_with.bits);
}

// Whether two values of one field are the same (the comparison
// changed_fields makes, per member type): Num by value and exactness.
inline bool same_field(Num a, Num b) { return same(a, b); }
inline bool same_field(bool a, bool b) { return a == b; }
inline bool same_field(uint8_t a, uint8_t b) { return a == b; }
inline bool same_field(int32_t a, int32_t b) { return a == b; }

// Which Fields differ between two states of one body (value or exactness).
DOWNSTROKE_API uint32_t changed_fields(const Body& before, const Body& after);
// The same, field by field, for a caller that already knows the two are not
// bitwise equal (changed_fields tries that first).
DOWNSTROKE_API uint32_t differing_fields(const Body& before, const Body& after);

}  // namespace ds
