// The physics view of one entity: plain data, decoded once from a plist and
// compared field by field afterwards to find what a frame changed.
#pragma once
#include <cstdint>

#include "number.hpp"

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
};

// Returns the bit for a skip symbol's name, or 0 for a name physics does not know.
uint16_t skip_bit(const char* name);
// The symbol name of one skip bit (for messages and stats).
const char* skip_name(uint16_t bit);

// Fields a step may write; a frame reports the changed ones as a mask of these.
// The bit order is the order a step writes several keys in (x y width height
// vx vy ay group-local-x group-local-y on-ground?).
enum Field : uint32_t {
    kFieldX = 1u << 0,
    kFieldY = 1u << 1,
    kFieldWidth = 1u << 2,   // only tweens write sizes and group offsets
    kFieldHeight = 1u << 3,
    kFieldVx = 1u << 4,
    kFieldVy = 1u << 5,
    kFieldAy = 1u << 6,
    kFieldLocalX = 1u << 7,
    kFieldLocalY = 1u << 8,
    kFieldOnGround = 1u << 9,
};
constexpr int kFieldCount = 10;

struct Body {
    Num x, y, w, h;          // top-left corner and size; the box is [x, x+w) × [y, y+h)
    Num vx, vy, ay;          // px/frame, and the one-shot vertical acceleration
    Num local_x, local_y;    // #:group-local-x / -y
    bool gravity = false;    // #:gravity?
    bool on_ground = false;  // #:on-ground?
    bool solid = false;      // #:solid?
    bool immovable = false;  // #:immovable?
    bool group_origin = false;
    uint16_t skip = 0;       // Skip bits
    // Identity tags assigned by the caller: equal #:id (or #:group-id) values
    // share a tag; 0 means the key is absent (or #f for the group).
    int64_t id = 0;
    int64_t group = 0;

    bool skips(uint16_t bit) const { return (skip & bit) != 0; }
    // Solid and not a ghost: takes part in push-apart and can hold others up.
    bool collides() const { return solid && !skips(kSkipEntityCollisions); }
};

// Which Fields differ between two states of one body (value or exactness).
uint32_t changed_fields(const Body& before, const Body& after);
// The same, field by field, for a caller that already knows the two are not
// bitwise equal (changed_fields tries that first).
uint32_t differing_fields(const Body& before, const Body& after);

// For a caller whose entities may lack some fields (a plist without #:vy):
// which fields to watch, and the order in which steps first wrote them. A
// step-by-step composition appends a missing key when a step first changes
// it and keeps it there even if a later step restores the value; this log
// lets a whole frame reproduce that key order. (The Scheme bindings also
// watch fields whose plist value a double cannot hold, such as 1/3: once a
// step wrote one, it must be written back even if the frame restored it.)
struct FirstWrites {
    uint16_t watched = 0;  // Field bits whose first write is still to come
    uint8_t count = 0;
    uint8_t order[kFieldCount] = {};  // Field bit indices, first write first

    // Records the watched fields among `changed`, in bit order.
    void note(uint32_t changed) {
        changed &= watched;
        for (; changed != 0; changed &= changed - 1) {
            const int bit = __builtin_ctz(changed);
            order[count++] = static_cast<uint8_t>(bit);
            watched &= static_cast<uint16_t>(~(1u << bit));
        }
    }
    uint32_t written() const {
        uint32_t mask = 0;
        for (int i = 0; i < count; ++i) mask |= 1u << order[i];
        return mask;
    }
};

}  // namespace ds
