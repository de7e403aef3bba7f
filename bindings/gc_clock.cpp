// SPDX-License-Identifier: MIT
#include "gc_clock.hpp"

#include <gc/gc.h>

#include <atomic>
#include <chrono>

#include "detail/stopwatch.hpp"

namespace ds::guile {

namespace {

// Written by whichever thread collects (with the allocation lock held),
// read by any: relaxed atomics, since a reading only needs each counter whole.
std::atomic<uint64_t> collections{0};
std::atomic<uint64_t> collecting_ns{0};
std::atomic<int64_t> started_at{0};
GC_on_collection_event_proc previous = nullptr;

int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

void GC_CALLBACK on_collection_event(GC_EventType event) {
    if (event == GC_EVENT_START) {
        started_at.store(now_ns(), std::memory_order_relaxed);
    } else if (event == GC_EVENT_END) {
        collecting_ns.fetch_add(static_cast<uint64_t>(now_ns() - started_at.load(std::memory_order_relaxed)),
                                std::memory_order_relaxed);
        collections.fetch_add(1, std::memory_order_relaxed);
    }
    if (previous != nullptr) previous(event);
}

}  // namespace

void start_gc_clock() {
    static const bool started = [] {
        previous = GC_get_on_collection_event();
        GC_set_on_collection_event(on_collection_event);
        return true;
    }();
    (void)started;
}

GcReading gc_reading() {
    return {collections.load(std::memory_order_relaxed), gc_ns(), static_cast<uint64_t>(GC_get_total_bytes())};
}

uint64_t gc_ns() { return collecting_ns.load(std::memory_order_relaxed); }

}  // namespace ds::guile
