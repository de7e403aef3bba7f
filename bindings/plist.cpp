// SPDX-License-Identifier: MIT
#include "plist.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>

#include "cons.hpp"
#include "detail/unwritten.hpp"
#include "list_walk.hpp"
#include "scm_number.hpp"

namespace ds::guile {

namespace {

// The body Field a physics key holds, or 0 for keys that are not fields.
uint32_t field_of(uint8_t k) {
    switch (k) {
#define DS_FIELD(Name, type, member, keyword, rule) \
    case k##Name: return kField##Name;
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
        default: return 0;
    }
}

// A number key's value as the core reads it: a finite real, exact only as
// an exact integer (semantics §1, §2); else the error naming the key.
bool decode_number(SCM key, SCM value, Num& out, Failure& f) {
    switch (num_from_scm(value, out)) {
        case NumCheck::Ok: return true;
        case NumCheck::NotReal:
            fail(f, "wrong-type-arg", scm_list_2(key, value), "entity key ~S: expected a real number, got ~S");
            return false;
        case NumCheck::NotFinite:
            fail(f, "wrong-type-arg", scm_list_2(key, value), "entity key ~S: expected a finite number, got ~S");
            return false;
        case NumCheck::OutOfRange:
            fail(f, "out-of-range", scm_list_2(key, value), "entity key ~S: expected a number %s, got ~S",
                 kDoubleRange);
            return false;
    }
    return false;
}

// Walks a proper, finite list of symbols, calling each(symbol); fails
// naming the key and the list otherwise.
template <class Each>
bool walk_symbols(SCM key, SCM list, Failure& f, Each&& each) {
    SCM p = list;
    size_t walked = 0;
    for (; scm_is_pair(p); p = SCM_CDR(p)) {
        if (++walked == kStepsBeforeCycleCheck && circular<1>(list)) [[unlikely]] {
            fail(f, "wrong-type-arg", scm_list_2(key, list), "entity key ~S: expected a list of symbols, got a circular list ~S");
            return false;
        }
        SCM sym = SCM_CAR(p);
        if (!scm_is_symbol(sym)) {
            fail(f, "wrong-type-arg", scm_list_2(key, list), "entity key ~S: expected a list of symbols, got ~S");
            return false;
        }
        each(sym);
    }
    if (!scm_is_null(p)) {
        fail(f, "wrong-type-arg", scm_list_2(key, list), "entity key ~S: expected a list of symbols, got ~S");
        return false;
    }
    return true;
}

// #:skip-pipelines as a mask of the steps it names (semantics §3): a proper
// list of symbols.
bool decode_skips(SCM key, SCM list, uint16_t& mask, Failure& f) {
    mask = 0;
    return walk_symbols(key, list, f, [&](SCM sym) {
        for (int bit = 0; bit < kSkipCount; ++bit)
            if (scm_is_eq(sym, keys->skip_symbol[bit])) mask |= static_cast<uint16_t>(1u << bit);
    });
}

// The rules of src/body_fields.def: how a value is read (decode) and
// written back (encode). `field` is the value's Field bit, 0 for a DS_KEY row.
struct Number {};
struct Flag {};
struct Skips {};
struct Tag {};
struct Id {};
struct Sides {};
struct Report {};
struct ReportMode {};
struct Unit {};
struct Scale {};
struct Cap {};
struct Category {};
struct CategoryList {};

// A bignum the decoded double holds exactly, such as 2^64, is not lossy: it
// is written back as itself (num_to_scm), so a frame that writes it and
// restores it leaves the plist as it was, as the step-by-step composition
// does. This is also what remember() (batch.cpp) assumes of an entity it
// wrote: were such a bignum lossy when decoded afresh but not when taken
// from the cache, step-scene's identity would hang on whether some other
// native call had reused the cache slot in between.
bool held_exactly(SCM v, Num n) { return n.exact && scm_is_true(scm_num_eq_p(v, num_to_scm(n))); }

bool decode(Number, SCM key, SCM v, Num& out, uint32_t field, Decoded& d, Failure& f) {
    // A boolean flag is never lossy (decode(Flag…)): watching #:on-ground? #f
    // would make a frame that flips it and flips it back (sub-frames) rewrite
    // the plist for nothing.
    if (!decode_number(key, v, out, f)) return false;
    if (!SCM_I_INUMP(v) && !SCM_REALP(v) && !held_exactly(v, out)) d.lossy |= static_cast<uint16_t>(field);
    return true;
}
bool decode(Flag, SCM, SCM v, bool& out, uint32_t field, Decoded& d, Failure&) {
    // A flag a step writes that holds a truthy non-boolean (#:on-ground? 'yes)
    // is lossy: once a step writes it, even back to true, it becomes #t, as
    // in the step-by-step composition (sub-frames that flip it and back).
    if (!scm_is_bool(v)) d.lossy |= static_cast<uint16_t>(field);
    out = scm_is_true(v);
    return true;
}
// #:contacts? (semantics §10): 'sides asks for each partner's side too; any
// other true value is the plain report, as before sides existed.
// #:contacts? (semantics §10): a flag, with one symbol of its own. Another
// symbol is a slip ('side, 'sidez) that would quietly give the plain report.
bool decode(ReportMode, SCM key, SCM v, uint8_t& out, uint32_t, Decoded&, Failure& f) {
    if (scm_is_symbol(v) && !scm_is_eq(v, keys->sides)) {
        fail(f, "wrong-type-arg", scm_list_2(key, v), "entity key ~S: expected #t, #f or 'sides, got ~S");
        return false;
    }
    out = scm_is_false(v) ? kContactsOff : scm_is_eq(v, keys->sides) ? kContactsSides : kContactsNames;
    return true;
}
bool decode(Skips, SCM key, SCM v, uint16_t& out, uint32_t, Decoded&, Failure& f) {
    return decode_skips(key, v, out, f);
}
// #:bounce (semantics §13): a finite real from 0 to 1.
bool decode(Unit, SCM key, SCM v, UnitNum& out, uint32_t, Decoded&, Failure& f) {
    Num n;
    if (!decode_number(key, v, n, f)) return false;
    out = UnitNum::of(n);
    if (n.v >= 0 && n.v <= 1) return true;
    fail(f, "out-of-range", scm_list_2(key, v), "entity key ~S: expected a number from 0 to 1, got ~S");
    return false;
}
// #:gravity-scale (semantics §14): any finite real.
bool decode(Scale, SCM key, SCM v, GravityScale& out, uint32_t, Decoded&, Failure& f) {
    return decode_number(key, v, out.n, f);
}
// #:max-vx, #:max-vy, #:drag (semantics §14): a finite real ≥ 0.
template <bool Unlimited>
bool decode(Cap, SCM key, SCM v, NonNegNum<Unlimited>& out, uint32_t, Decoded&, Failure& f) {
    Num n;
    if (!decode_number(key, v, n, f)) return false;
    out = NonNegNum<Unlimited>::of(n);
    if (n.v >= 0) return true;
    fail(f, "out-of-range", scm_list_2(key, v), "entity key ~S: expected a number ≥ 0, got ~S");
    return false;
}
// Categories are checked here and turned into bits by a CategoryTable.
bool decode(Category, SCM key, SCM v, CategoryBit&, uint32_t, Decoded& d, Failure& f) {
    if (!scm_is_symbol(v)) {
        fail(f, "wrong-type-arg", scm_list_2(key, v), "entity key ~S: expected a category symbol, got ~S");
        return false;
    }
    d.category = v;
    return true;
}
bool decode(CategoryList, SCM key, SCM v, CategoryMask&, uint32_t, Decoded& d, Failure& f) {
    if (!walk_symbols(key, v, f, [](SCM) {})) return false;
    d.collides_with = v;
    return true;
}
// The pairs and vector slots an #:id or #:group-id may hold. identity_tag
// compares ids with equal?, which never ends on two circular lists and
// recurses once per nesting level: a bound on the cells keeps each
// comparison short and refuses every cyclic id, while real ids (a symbol, a
// string, a short list such as (enemy 3)) are far smaller.
constexpr int kMaxIdCells = 1024;

// Whether v holds at most `budget` pairs and vector slots (spent as counted).
bool id_within(SCM v, int& budget) {
    if (scm_is_pair(v)) {
        for (; scm_is_pair(v); v = SCM_CDR(v))
            if (--budget < 0 || !id_within(SCM_CAR(v), budget)) return false;
        return true;  // an improper tail is an atom
    }
    if (scm_is_vector(v))
        for (size_t i = 0, n = scm_c_vector_length(v); i < n; ++i)
            if (--budget < 0 || !id_within(scm_c_vector_ref(v, i), budget)) return false;
    return true;
}

bool decode_identity(SCM key, SCM v, int64_t& out, Failure& f) {
    int budget = kMaxIdCells;
    if (!id_within(v, budget)) {
        fail(f, "wrong-type-arg", scm_list_3(key, scm_from_int(kMaxIdCells), v),
             "entity key ~S: expected an id of at most ~S pairs and vector slots (never a circular list), got ~S");
        return false;
    }
    out = identity_tag(v);
    return true;
}

bool decode(Tag, SCM key, SCM v, int64_t& out, uint32_t, Decoded&, Failure& f) {
    return decode_identity(key, v, out, f);
}
bool decode(Id, SCM key, SCM v, int64_t& out, uint32_t, Decoded& d, Failure& f) {
    d.id = v;
    return decode_identity(key, v, out, f);
}

// #:blocked is the engine's (semantics §10): a list of the sides in the
// order left right up down reads as those sides; any other value as none,
// to be rewritten by the next write (kSidesUnwritten).
uint8_t sides_of(SCM list) {
    uint8_t mask = 0;
    int next = 0;  // the sides must come in order, each once
    SCM p = list;
    for (; scm_is_pair(p) && next < 4; p = SCM_CDR(p)) {
        int bit = next;
        while (bit < 4 && !scm_is_eq(SCM_CAR(p), keys->side_symbol[bit])) ++bit;
        if (bit == 4) return kSidesUnwritten;
        mask |= static_cast<uint8_t>(1u << bit);
        next = bit + 1;
    }
    return scm_is_null(p) ? mask : static_cast<uint8_t>(kSidesUnwritten);
}

bool decode(Sides, SCM, SCM v, uint8_t& out, uint32_t, Decoded&, Failure&) {
    out = sides_of(v);
    return true;
}
// The report's names are compared as values when written (contact_report.hpp),
// with the raw values kept here.
SCM& raw_report(Decoded& d, uint32_t field) { return field == kFieldTouching ? d.touching : d.standing_on; }
bool decode(Report, SCM, SCM v, uint8_t& out, uint32_t field, Decoded& d, Failure&) {
    out = 0;
    raw_report(d, field) = v;
    return true;
}
bool decode(Report, SCM, SCM v, int32_t& out, uint32_t field, Decoded& d, Failure&) {
    out = kStandingUnknown;
    raw_report(d, field) = v;
    return true;
}

SCM encode(Number, Num n) { return num_to_scm(n); }
SCM encode(Flag, bool flag) { return scm_from_bool(flag); }
SCM encode(Sides, uint8_t mask) {
    SCM list = SCM_EOL;
    for (int bit = 3; bit >= 0; --bit)
        if (mask & (1u << bit)) list = scm_cons(keys->side_symbol[bit], list);
    return list;
}
// A placeholder the bindings replace with the names (report_edits).
template <class T>
SCM encode(Report, T) { return SCM_UNSPECIFIED; }

// The report keys of an entity that does not opt in are never written, and
// one that does reads an absent key as still to be written.
void settle_report(Decoded& d) {
    Body& b = d.body;
    if (!b.contacts) {
        b.blocked = b.touching = 0;
        b.standing_on = 0;
        return;
    }
    if (!d.has(kBlocked)) b.blocked = kSidesUnwritten;
    if (!d.has(kTouching)) b.touching = kReportUnwritten;
    if (!d.has(kStandingOn)) b.standing_on = kStandingAbsent;
}

// Records where physics key k first occurs, if it is a field's.
void place(FieldPlaces& places, uint8_t k, size_t index) {
    const uint32_t field = field_of(k);
    if (field != 0 && index <= FieldPlaces::kMaxPlace) places.at[__builtin_ctz(field)] = static_cast<uint8_t>(index);
}

// Physics key k's value, checked and stored in the body (semantics §2).
bool decode_value(uint8_t k, SCM key, SCM v, Decoded& d, Failure& f) {
    Body& b = d.body;
    switch (k) {
#define DS_FIELD(Name, type, member, keyword, rule) \
    case k##Name: return decode(rule{}, key, v, b.member, kField##Name, d, f);
#define DS_KEY(Name, type, member, keyword, rule) \
    case k##Name: return decode(rule{}, key, v, b.member, 0, d, f);
#include "body_fields.def"
        case kTween: d.tween = v; return true;
        default: return true;
    }
}

}  // namespace

namespace {

// identity_tag's table of interned ids: value -> tag, under `lock` (any
// thread may decode). A real Guile hash table, kept from the collector for
// good; the mutex and counter are plain C++ and never freed either.
struct InternedIds {
    SCM table = SCM_BOOL_F;
    std::mutex lock;
    int64_t next = 1;  // the next tag is (next << 1) | 1: odd, never an SCM's raw bits
};

InternedIds& interned_ids() {
    static InternedIds* ids = [] {
        auto* p = new InternedIds;
        p->table = scm_permanent_object(scm_c_make_hash_table(64));
        return p;
    }();
    return *ids;
}

void unlock_ids(void* lock) { static_cast<std::mutex*>(lock)->unlock(); }

}  // namespace

int64_t identity_tag(SCM v) {
    if (scm_is_false(v)) return 0;
    // Immediates, symbols and keywords are equal? exactly when eq?.
    if (SCM_IMP(v) || scm_is_symbol(v) || scm_is_keyword(v))
        return static_cast<int64_t>(SCM_UNPACK(v));
    InternedIds& ids = interned_ids();
    int64_t tag = 0;
    // equal? may run Scheme (a GOOPS equal? method) and escape: the dynwind
    // releases the lock however the lookup ends.
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    ids.lock.lock();
    scm_dynwind_unwind_handler(unlock_ids, &ids.lock, SCM_F_WIND_EXPLICITLY);
    const SCM known = scm_hash_ref(ids.table, v, SCM_BOOL_F);  // by equal?
    if (scm_is_true(known)) {
        tag = scm_to_int64(known);
    } else {
        tag = static_cast<int64_t>((static_cast<uint64_t>(ids.next++) << 1) | 1);
        scm_hash_set_x(ids.table, v, scm_from_int64(tag));
    }
    scm_dynwind_end();
    return tag;
}

bool decode_entity(SCM plist, Decoded& d, Failure& f) {
    d = Decoded{};
    SCM p = plist;
    size_t passed = 0, index = 0;
    SlipTable* slips = nullptr;  // this thread's, from the first unknown key
    for (; scm_is_pair(p); p = SCM_CDR(SCM_CDR(p)), ++index) {
        SCM key = SCM_CAR(p);
        const uint8_t k = keys->lookup(key);  // a physics key is a keyword: no need to ask
        if (k == kNotPhysics && !scm_is_keyword(key)) {
            fail(f, "wrong-type-arg", scm_list_2(key, plist), "malformed entity: ~S in key position of ~S");
            return false;
        }
        if (!scm_is_pair(SCM_CDR(p))) {
            fail(f, "wrong-type-arg", scm_list_2(key, plist), "malformed entity: key ~S has no value in ~S");
            return false;
        }
        if (k == kNotPhysics) note_unknown_key(slips, key, d.slips);
        if (k == kNotPhysics || d.has(static_cast<PhysKey>(k))) {  // first occurrence wins
            // A circular plist has finitely many first occurrences of physics
            // keys, then only entries like this one: it always gets here.
            if (++passed == kStepsBeforeCycleCheck && circular<2>(plist)) [[unlikely]] {
                fail_circular(f, "malformed entity", "a keyword plist", plist);
                return false;
            }
            continue;
        }
        d.present |= uint64_t{1} << k;
        place(d.places, k, index);
        if (!decode_value(k, key, SCM_CAR(SCM_CDR(p)), d, f)) return false;
    }
    if (!scm_is_null(p)) {
        fail(f, "wrong-type-arg", scm_list_1(plist), "malformed entity: expected a keyword plist, got ~S");
        return false;
    }
    d.places.pairs = static_cast<uint16_t>(std::min(index, FieldPlaces::kMaxPlace + 2));
    settle_report(d);
    return true;
}

SCM plist_get(SCM plist, SCM key, SCM fallback) {
    for (SCM p = plist; scm_is_pair(p) && scm_is_pair(SCM_CDR(p)); p = SCM_CDR(SCM_CDR(p)))
        if (scm_is_eq(SCM_CAR(p), key)) return SCM_CAR(SCM_CDR(p));
    return fallback;
}

SCM rewrite_plist(SCM plist, const Edit* edits, size_t count) {
    if (count == 0) return plist;
    // Pass 1: where is each edited key, and how far must we copy?
    uint64_t found = 0;  // bit i: edits[i].key occurs
    size_t last = 0, index = 0;
    const uint64_t all = count == 64 ? ~0ull : (1ull << count) - 1;
    for (SCM p = plist; scm_is_pair(p) && found != all; p = SCM_CDR(SCM_CDR(p)), ++index)
        for (size_t i = 0; i < count; ++i)
            if (!((found >> i) & 1u) && scm_is_eq(SCM_CAR(p), edits[i].key)) {
                found |= 1ull << i;
                last = index + 1;
            }
    bool appends = false;
    for (size_t i = 0; i < count; ++i) appends |= !((found >> i) & 1u) && !edits[i].remove && !goes_in_front(edits[i].field);
    SCM head = SCM_EOL, tail = SCM_BOOL_F;
    const Conser cons;
    auto emit = [&](SCM key, SCM value) {
        SCM cell = cons(key, cons(value, SCM_EOL));
        if (scm_is_false(tail)) head = cell;
        else SCM_SETCDR(tail, cell);  // a fresh pair: no check, and the collector needs no barrier
        tail = SCM_CDR(cell);
    };
    // Pass 2: copy up to the last edited key (all of it when appending).
    uint64_t done = 0;
    SCM p = plist;
    for (index = 0; scm_is_pair(p) && (appends || index < last); p = SCM_CDR(SCM_CDR(p)), ++index) {
        SCM key = SCM_CAR(p), value = SCM_CAR(SCM_CDR(p));
        size_t i = 0;
        while (i < count && (((done >> i) & 1u) || !scm_is_eq(key, edits[i].key))) ++i;
        if (i == count) {
            emit(key, value);
            continue;
        }
        done |= 1ull << i;
        if (!edits[i].remove) emit(key, edits[i].value);
    }
    for (size_t i = 0; i < count; ++i)
        if (!((found >> i) & 1u) && !edits[i].remove && !goes_in_front(edits[i].field)) emit(edits[i].key, edits[i].value);
    SCM result = p;  // when everything before p was removed
    if (scm_is_true(tail)) {
        SCM_SETCDR(tail, p);
        result = head;
    }
    for (size_t i = 0; i < count; ++i)
        if (!((found >> i) & 1u) && !edits[i].remove && goes_in_front(edits[i].field))
            result = cons(edits[i].key, cons(edits[i].value, result));
    return result;
}

bool all_placed(const Edit* edits, size_t count, const FieldPlaces& places) {
    for (size_t i = 0; i < count; ++i) {
        const Edit& e = edits[i];
        if (e.remove || e.field < 0) return false;
        if (places.at[e.field] == FieldPlaces::kUnplaced && !(goes_in_front(e.field) && places.absent(e.field)))
            return false;
    }
    return count != 0;
}

SCM rewrite_placed(SCM plist, const Edit* edits, size_t count, const FieldPlaces& places) {
    // By pair index up to the last replaced pair: which edit replaces its value.
    int8_t edit_at[FieldPlaces::kMaxPlace + 1];
    size_t last = 0;
    auto replaces = [&](size_t i) { return places.at[edits[i].field] != FieldPlaces::kUnplaced; };
    for (size_t i = 0; i < count; ++i)
        if (replaces(i)) last = std::max<size_t>(last, places.at[edits[i].field] + 1u);
    std::fill_n(edit_at, last, int8_t{-1});
    for (size_t i = 0; i < count; ++i)
        if (replaces(i)) edit_at[places.at[edits[i].field]] = static_cast<int8_t>(i);
    const Conser cons;
    SCM p = plist, head = SCM_EOL, tail = SCM_EOL;
    for (size_t index = 0; index < last; ++index, p = SCM_CDR(SCM_CDR(p))) {
        const SCM value = edit_at[index] < 0 ? SCM_CAR(SCM_CDR(p)) : edits[edit_at[index]].value;
        SCM cell = cons(SCM_CAR(p), cons(value, SCM_EOL));
        if (index == 0) head = cell;
        else SCM_SETCDR(tail, cell);
        tail = SCM_CDR(cell);
    }
    SCM result = p;
    if (last != 0) {
        SCM_SETCDR(tail, p);
        result = head;
    }
    for (size_t i = 0; i < count; ++i)  // the absent report fields (all_placed)
        if (!replaces(i)) result = cons(edits[i].key, cons(edits[i].value, result));
    return result;
}

void FieldPlaces::put_in_front(int field) {
    for (uint8_t& a : at)
        if (a != kUnplaced) a = a < kMaxPlace ? static_cast<uint8_t>(a + 1) : kUnplaced;
    at[field] = 0;
    if (pairs <= kMaxPlace + 1) ++pairs;
}

FieldPlaces places_of(SCM plist) {
    FieldPlaces places;
    // One bit per PhysKey, as Decoded::present (keys.hpp asserts they fit).
    uint64_t seen = 0;
    size_t index = 0;
    SCM p = plist;
    for (; scm_is_pair(p) && index <= FieldPlaces::kMaxPlace; p = SCM_CDR(SCM_CDR(p)), ++index) {
        const uint8_t k = keys->lookup(SCM_CAR(p));
        if (k == kNotPhysics || ((seen >> k) & 1u)) continue;
        seen |= uint64_t{1} << k;
        place(places, k, index);
    }
    if (!scm_is_pair(p)) places.pairs = static_cast<uint16_t>(index);
    return places;
}

namespace {

// The plist key and current value of one Field (by bit index).
Edit field_edit(int bit, const Body& b) {
    switch (bit) {
#define DS_FIELD(Name, type, member, keyword, rule) \
    case kFieldBit##Name: return {keys->key[k##Name], encode(rule{}, b.member), false, kFieldBit##Name};
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
        default: __builtin_unreachable();  // bit < kFieldCount
    }
}

bool finite(Num n) { return std::isfinite(n.v); }
template <class T>
bool finite(T) { return true; }

bool out_of_range(SCM key, double v, Failure& f) {
    fail(f, "out-of-range", scm_list_2(key, scm_from_double(v)),
         "entity key ~S: the result ~S is beyond the range of a double");
    return false;
}
double value_of(Num n) { return n.v; }
template <class T>
double value_of(T) { return 0; }

}  // namespace

bool check_finite(const Body& b, uint32_t fields, Failure& f) {
    // In Field bit order, the first one that is not finite.
#define DS_FIELD(Name, type, member, keyword, rule) \
    if ((fields & kField##Name) != 0 && !finite(b.member)) return out_of_range(keys->key[k##Name], value_of(b.member), f);
#define DS_KEY(Name, type, member, keyword, rule)
#include "body_fields.def"
    return true;
}

uint16_t watched_fields(const Decoded& d) {
    uint16_t absent = 0;
    for (uint8_t k = 0; k < kPhysKeyCount; ++k)
        if (!d.has(static_cast<PhysKey>(k))) absent |= static_cast<uint16_t>(field_of(k));
    return absent | d.lossy;
}

size_t field_edits(uint32_t changed, const Body& after, Edit* out, const FirstWrites* writes) {
    size_t n = 0;
    // Watched fields a step wrote are written whatever their final value: an
    // absent key goes last, in the order written (where the composition
    // appended it), or in front if a report field's (rewrite_plist); a lossy
    // one is replaced in place.
    const uint32_t appended = writes ? writes->written() : 0;
    for (uint32_t rest = changed & ~appended; rest != 0; rest &= rest - 1)
        out[n++] = field_edit(__builtin_ctz(rest), after);
    if (writes)
        for (int i = 0; i < writes->count; ++i) out[n++] = field_edit(writes->order[i], after);
    return n;
}

}  // namespace ds::guile
