// SPDX-License-Identifier: MIT
// Entity plists ⇄ bodies. Decoding walks a plist once and picks out the
// physics keys; encoding rewrites only what changed, in place order, and
// shares the unchanged tail — an unchanged entity comes back as itself.
#pragma once
#include <libguile.h>

#include <cstddef>
#include <cstdint>

#include "body.hpp"
#include "detail/first_writes.hpp"
#include "failure.hpp"
#include "key_slips.hpp"
#include "keys.hpp"

namespace ds::guile {

// Where the key of each Field first occurs in a plist, as a pair index (key
// k of (k0 v0 k1 v1 …) is pair k), or kUnplaced when it is absent or beyond
// kMaxPlace. Encoding a cached entity then copies just the prefix up to the
// last edited key, in one walk and without comparing a key (rewrite_placed).
struct FieldPlaces {
    static constexpr uint8_t kUnplaced = 255;
    static constexpr size_t kMaxPlace = 254;  // a uint8_t, kUnplaced aside
    uint8_t at[kFieldCount];
    // How many pairs the plist has, up to kMaxPlace + 2 ("more"): while every
    // pair has a place, an unplaced field is known to be absent, and a report
    // key's first write goes in front without a walk (rewrite_placed).
    uint16_t pairs = kMaxPlace + 2;
    FieldPlaces() { for (uint8_t& a : at) a = kUnplaced; }
    bool absent(int field) const { return at[field] == kUnplaced && pairs <= kMaxPlace + 1; }
    // The places once an absent field's key is put in front of the plist.
    void put_in_front(int field);
};

// The fields the contact report adds beyond the seed (semantics §10, and
// #:crushed? of §11): a step that writes one for the first time puts it at
// the front of the plist, each before those already there, so the whole
// plist is shared as its tail. Appending copied every pair: on a frame that
// first reports fresh sensor shots, the copies made encoding several times
// dearer (docs/benchmarks.org, "Cheap report keys"). The seed's own keys are
// still appended, as the seed's examples show.
constexpr uint32_t kFrontFields = kFieldBlocked | kFieldTouching | kFieldStandingOn | kFieldCrushed;
inline bool goes_in_front(int8_t field) { return field >= 0 && ((kFrontFields >> field) & 1u); }

struct Decoded {
    Body body;
    FieldPlaces places;
    uint64_t present = 0;  // bit k set: PhysKey k occurs in the plist
    uint16_t lossy = 0;    // Field bits whose value is not a fixnum or flonum (1/3, 2^70)
    SCM tween = SCM_BOOL_F;
    SCM id = SCM_BOOL_F;   // the raw #:id, for equal? comparisons
    // The raw #:category and #:collides-with (checked), SCM_UNDEFINED when
    // absent: a CategoryTable turns them into the body's bits.
    SCM category = SCM_UNDEFINED;
    SCM collides_with = SCM_UNDEFINED;
    // The raw #:touching and #:standing-on, SCM_UNDEFINED when absent: a
    // frame compares its report with them without walking the plist again.
    SCM touching = SCM_UNDEFINED;
    SCM standing_on = SCM_UNDEFINED;
    EntitySlips slips;  // keys that are a slip of an engine key (decode_batch queues them)
    bool categorized() const { return !SCM_UNBNDP(category) || !SCM_UNBNDP(collides_with); }
    bool has(PhysKey k) const { return (present >> k) & 1u; }
};

// Fills d from an entity plist. On a malformed plist or a wrongly typed
// value, records a Failure naming the procedure, key and value.
bool decode_entity(SCM plist, Decoded& d, Failure& f);

// An identity tag for #:id / #:group-id values: two values get equal tags
// exactly when they are equal?; #f and absence give 0. Tags stay valid for
// the life of the process (the core compares them within a frame, cached
// decodings keep them across frames).
// Immediates (small integers, characters, booleans …), symbols and keywords
// are equal? exactly when eq?: their tag is their raw bits, which on 64-bit
// Guile 3 are never odd (heap pointers end in 000, fixnums in x10, other
// immediates in 100). Any other value is interned in a process-wide equal?
// hash table that gives each distinct value an odd tag of its own, so the
// two kinds never meet. Memory: one table entry (and the value kept alive)
// per distinct non-immediate, non-symbol id ever seen — strings, big or
// inexact numbers, lists …; symbols, keywords and small integers cost
// nothing. As with any hash-table key, an id must not be mutated once used.
// decode_entity refuses an id of more than kMaxIdCells (plist.cpp) pairs and vector
// slots (every circular one) before it gets here: equal? would not end.
int64_t identity_tag(SCM value);

struct Edit {
    SCM key;
    SCM value;
    bool remove = false;
    int8_t field = -1;  // the Field bit index the key holds, when it is a field's (field_edits)
};

// A new plist with each edit applied to the first occurrence of its key
// (removed when `remove`); absent keys are appended in edit order, except a
// report field's (goes_in_front), put in front, each before the previous.
// Conses only up to the last edited key and shares the rest; returns plist
// itself when there are no edits.
SCM rewrite_plist(SCM plist, const Edit* edits, size_t count);

// Whether rewrite_placed can apply these edits: each replaces a field whose
// first occurrence `places` knows, or puts a report field `places` knows to
// be absent in front.
bool all_placed(const Edit* edits, size_t count, const FieldPlaces& places);
// rewrite_plist for edits that all_placed accepts: the same new plist, built
// in one walk of the prefix up to the last edited pair.
SCM rewrite_placed(SCM plist, const Edit* edits, size_t count, const FieldPlaces& places);
// The places of a plist decode_entity accepted (walked again).
FieldPlaces places_of(SCM plist);

// The Field bits a frame must watch: the fields a decoded plist lacks (a
// first write appends them) and the lossy ones (a write must reach the plist
// even if the frame restores the value read).
uint16_t watched_fields(const Decoded& d);

// Collects the edits for the fields in `changed` (changed_fields of the
// body before and after), plus (with `writes`) every absent field a step
// wrote, appended in the order written; values are taken from `after`.
// Returns how many were written to out (room for 16 is enough).
size_t field_edits(uint32_t changed, const Body& after, Edit* out,
                   const FirstWrites* writes = nullptr);

// Fails (out-of-range, naming the key and the value) when one of the Field
// bits in `fields` (those a step changed: decoding already refused non-finite
// input) left the range of a double: finite inputs near ±1.8e308 can
// overflow, and the next step would refuse the infinity less helpfully.
bool check_finite(const Body& b, uint32_t fields, Failure& f);

// The value of the first occurrence of key in plist, or fallback. No checks:
// for plists already validated by decode_entity.
SCM plist_get(SCM plist, SCM key, SCM fallback);

}  // namespace ds::guile
