// SPDX-License-Identifier: MIT
// Ground detection against a frame's supporters (the solid bodies copied out
// at the frame's start), optionally through an index: the core's machinery
// behind detect_on_solid (ground.hpp).
#pragma once
#include <cstddef>
#include <span>

#include "../ground.hpp"
#include "support_index.hpp"
#include "supporter.hpp"

namespace ds {

// entity_supports and rests_on (ground.hpp) for a supporter, which collides
// by construction.
bool entity_supports(const Body& b, const Supporter& other);
bool rests_on(const Body& b, const Supporter& other);

// Whether candidate k of a scene or supporter list, in which b's own slot is
// self_slot (or -1), is b itself or shares b's nonzero id: such a candidate
// neither holds b up nor gives it a resting contact.
template <class Other>
bool is_self(const Body& b, const Other& other, std::ptrdiff_t k, std::ptrdiff_t self_slot) {
    return k == self_slot || (b.id != 0 && other.id == b.id);
}

// The same against the frame's supporters (self_slot: b's own slot there).
bool detect_on_supporters(Body& b, std::span<const Supporter> supporters, std::ptrdiff_t self_slot,
                          const TileGrid* grid);
// The same, finding the candidates through an index built on `supporters`.
bool detect_on_supporters(Body& b, std::span<const Supporter> supporters, SupportIndex& index,
                          std::ptrdiff_t self_slot, const TileGrid* grid);

// first_supporter (ground.hpp) against the frame's supporters, by slot.
std::ptrdiff_t first_supporter(const Body& b, std::span<const Supporter> supporters,
                               std::ptrdiff_t self_slot);
std::ptrdiff_t first_supporter(const Body& b, std::span<const Supporter> supporters,
                               SupportIndex& index, std::ptrdiff_t self_slot);

}  // namespace ds
