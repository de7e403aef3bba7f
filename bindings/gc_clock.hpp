// SPDX-License-Identifier: MIT
// What the collector has cost this process: collections counted and timed
// by the wall clock through Boehm's collection events, and the bytes
// allocated. Read before and after a frame, the difference is that frame's
// share. Not Guile's own gc-time-taken: that is process CPU time, which adds
// up every marking thread (about 1.8 times a collection's pause on the
// 2-core machine of docs/benchmarks.org), and is only reachable by consing a
// (gc-stats) alist.
#pragma once
#include <cstdint>

namespace ds::guile {

struct GcReading {
    uint64_t collections = 0;
    uint64_t ns = 0;     // wall time inside collections (start to end event)
    uint64_t bytes = 0;  // allocated since start, as Boehm counts it: a thread's
                         // free list is counted when it is refilled, so a
                         // reading is exact to a few KB, not to the byte
};

// Installs the event handler (once; the handler it replaces, if any, is
// still called). Must run after Guile has started the collector.
void start_gc_clock();

GcReading gc_reading();
// gc_reading().ns alone: one atomic load, without the allocation
// lock GC_get_total_bytes takes, for timers read several times a frame.
uint64_t gc_ns();

inline GcReading operator-(const GcReading& a, const GcReading& b) {
    return {a.collections - b.collections, a.ns - b.ns, a.bytes - b.bytes};
}

}  // namespace ds::guile
