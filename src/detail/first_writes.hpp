// SPDX-License-Identifier: MIT
// The bindings' key-order log, passed through Frame::step_physics: not part
// of the public API, because only a caller whose entities may lack fields
// (the Scheme plists) needs it; a C++ program's bodies have every field.
#pragma once
#include <cstdint>

#include "../body.hpp"

namespace ds {

static_assert(kFieldCount <= 16, "FirstWrites::watched and Decoded::lossy hold Field bits in 16 bits");

// Which fields to watch, and the order in which steps first wrote them. A
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
