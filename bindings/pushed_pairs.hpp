// SPDX-License-Identifier: MIT
// The debug overlay's log of the pairs push-apart resolved: turned on by
// %note-pushed-pairs!, filled by step-scene and the bulk
// resolve-entity-collisions, read by game-draw. The core takes the log as a
// parameter (Frame::note_pairs, ContactScratch::log); it is kept per thread
// here because these are free procedures called from Scheme, with nothing
// between their calls to hold it.
#pragma once
#include "contacts.hpp"

namespace ds::guile {

PairLog*& pushed_pairs();  // this thread's log, or nullptr: note nothing

}  // namespace ds::guile
