// SPDX-License-Identifier: MIT
#include "key_slips.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "keys.hpp"
#include "registry.hpp"

namespace ds::guile {

namespace {

// The entity keys the engine reads besides the physics keys (keys.hpp):
// the renderer's and the camera's.
constexpr const char* kOtherEngineKeys[] = {"sprite",   "flip-x?",   "visible?",        "color",
                                            "sprite-offset", "sprite-scale", "rotation", "animation",
                                            "animation-start", "tag"};
constexpr size_t kOtherCount = sizeof kOtherEngineKeys / sizeof *kOtherEngineKeys;
constexpr size_t kEngineKeyCount = kPhysKeyCount + kOtherCount;

const char* engine_key(size_t i) { return i < kPhysKeyCount ? key_name(static_cast<uint8_t>(i)) : kOtherEngineKeys[i - kPhysKeyCount]; }

// The longest engine key is 15 characters (animation-start): a name more than
// two longer is no slip, and the distance table stays on the stack.
constexpr size_t kMaxCompared = 16;

// Edits (a character inserted, removed or replaced, or two neighbours
// swapped) between a and b, both at most kMaxCompared long.
size_t distance(const char* a, size_t n, const char* b, size_t m) {
    size_t d[kMaxCompared + 1][kMaxCompared + 1];
    for (size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (size_t i = 1; i <= n; ++i)
        for (size_t j = 1; j <= m; ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[n][m];
}

// How many edits a slip of an engine key of `len` characters may be: none
// for keys of up to 3 (x, vx, id, tag: the author's #:dx, #:hp, #:ix are as
// near), one up to 7 (#:bounse, #:sensr?), two from 8 (#:colides-with).
// A slip also keeps the first letter: #:weight is not #:height, nor #:life
// anything, and typing slips rarely fall there.
size_t edits_allowed(size_t len) { return len <= 3 ? 0 : len <= 7 ? 1 : 2; }

constexpr uint8_t kFar = SlipTable::kFar;

// The engine key a name is a slip of, or kFar (also for an engine key itself).
uint8_t suggestion_for(const char* name, size_t n) {
    if (n == 0 || n > kMaxCompared) return kFar;
    uint8_t best = kFar;
    size_t best_d = 3;
    for (size_t i = 0; i < kEngineKeyCount; ++i) {
        const char* known = engine_key(i);
        const size_t m = std::strlen(known);
        if (m == n && std::memcmp(name, known, n) == 0) return kFar;  // #:sprite, #:tag: read by the engine
        if (!near_miss(name, n, known)) continue;
        const size_t d = distance(name, n, known, m);
        if (d < best_d) best = static_cast<uint8_t>(i), best_d = d;
    }
    return best;
}

thread_local SlipTable* table = nullptr;  // made at the first unknown key, kept for the thread's life

uint8_t classify(SCM keyword) {
    size_t n = 0;
    char* name = scm_to_utf8_stringn(scm_symbol_to_string(scm_keyword_to_symbol(keyword)), &n);
    const uint8_t s = suggestion_for(name, n);
    std::free(name);
    return s;
}

}  // namespace

bool near_miss(const char* name, size_t n, const char* known) {
    const size_t m = std::strlen(known), allowed = edits_allowed(m);
    if (allowed == 0 || n == 0 || n > kMaxCompared || name[0] != known[0]) return false;
    if ((n > m ? n - m : m - n) > allowed) return false;
    const size_t d = distance(name, n, known, m);
    return d >= 1 && d <= allowed;
}

SlipTable::SlipTable() {
    std::fill_n(key, kSlots, SCM_BOOL_F);
    std::fill_n(queued, kSlots, false);
}

bool SlipTable::add(SCM keyword, size_t slot) {
    if (used == kMaxKeys) return false;
    key[slot] = scm_gc_protect_object(keyword);
    suggestion[slot] = classify(keyword);
    ++used;
    return true;
}

SlipTable& this_thread_slips() {
    if (!table) table = new SlipTable;
    return *table;
}

void queue_slips(const EntitySlips& slips, size_t index, SCM id) {
    SlipTable& t = this_thread_slips();
    for (uint8_t i = 0; i < slips.count; ++i) {
        const uint16_t slot = slips.slot[i];
        if (t.queued[slot]) continue;
        t.queued[slot] = true;
        if (scm_is_false(t.pending)) t.pending = scm_gc_protect_object(scm_c_make_vector(1, SCM_EOL));
        const SCM report = scm_list_4(t.key[slot], scm_from_utf8_keyword(engine_key(t.suggestion[slot])),
                                      scm_from_size_t(index), id);
        SCM_SIMPLE_VECTOR_SET(t.pending, 0, scm_cons(report, SCM_SIMPLE_VECTOR_REF(t.pending, 0)));
    }
}

namespace {

// The near misses decoded on this thread since the last call, oldest first,
// as (key suggestion index id); each key is queued again after this.
SCM take_key_slips() {
    if (!table || scm_is_false(table->pending)) return SCM_EOL;
    const SCM reports = SCM_SIMPLE_VECTOR_REF(table->pending, 0);
    if (scm_is_null(reports)) return SCM_EOL;
    SCM_SIMPLE_VECTOR_SET(table->pending, 0, SCM_EOL);
    std::fill_n(table->queued, SlipTable::kSlots, false);
    return scm_reverse(reports);
}

}  // namespace

void register_key_slip_procedures() {
    define_procedure<0, 0, 0, take_key_slips>("%take-key-slips",
        "() → ((key suggestion index id) …): the entity keys decoded on this thread since the last call that "
        "are a slip of an engine key (#:sensr? for #:sensor?), oldest first, each once; INDEX is the entity's "
        "place in its list, ID its #:id or #f. The engine reports them after each frame.");
}

}  // namespace ds::guile
