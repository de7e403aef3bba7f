// SPDX-License-Identifier: MIT
// libFuzzer target for the entity plist decoder (bindings/plist.*, batch.*)
// and the native steps behind it. Guile starts once; each input is read as a
// recipe for an entity list: keys from the physics key table, unknown
// keywords and non-keywords, values of every kind (fixnums, bignums, flonums
// with NaN, ±inf and -0.0, rationals, complex numbers, booleans, strings,
// symbols, lists with dotted tails). Each entity goes through decode_entity,
// then the list through every native procedure that takes entities. A Scheme
// error is the boundary refusing the input, as it should; a crash, a
// sanitizer report, a C++ exception reaching Guile (an abort) or a hang is a
// finding.
//
// Circular tails (plists, #:skip-pipelines lists, entity lists) are built
// too: the native walks must refuse them (docs/limits.org, "Lists").
// DS_FUZZ_CIRCULAR=0 leaves them out, to tell a cycle finding from another.
// DS_FUZZ_SHOW=1 prints each entity list built and what a frame made of it,
// to see what a failing input is (tools/fuzz.sh replay plist FILE).
#include <libguile.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "keys.hpp"
#include "plist.hpp"

extern "C" void ds_init_native();

namespace {

// The input, consumed a byte (or eight) at a time; zeros once it runs out.
struct Recipe {
    const uint8_t* p;
    size_t n;
    uint8_t byte() { return n ? (--n, *p++) : 0; }
    uint64_t word() {
        uint64_t w = 0;
        for (int i = 0; i < 8; ++i) w = (w << 8) | byte();
        return w;
    }
    int64_t signed_word() { return static_cast<int64_t>(word()); }
    double bits_as_double() {
        const uint64_t w = word();
        double d;
        std::memcpy(&d, &w, sizeof d);
        return d;
    }
};

// Bounds on one input's shape: enough for every path of a frame (several
// entities, nested lists), small enough that every input runs in microseconds.
constexpr int kMaxEntities = 6;
constexpr int kMaxPairs = 12;
constexpr int kMaxListLength = 5;
constexpr int kMaxDepth = 2;

// The procedures stay reachable from (downstroke native) and the tilemap is a
// permanent object, so the collector keeps them whatever it makes of this struct.
struct Natives {
    SCM step_entities, single[5], tile_steps[2], detect_on_solid, list_steps[3];
    SCM tilemap;  // 8×4 cells of 16 px, the bottom row solid
    bool circular = true;
    bool show = false;
};
Natives natives;

SCM special_double(uint8_t which) {
    constexpr double kSpecial[] = {std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(),
                                   -0.0, 0.0, std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::denorm_min(), 1e308, 0.5, 16.0};
    return scm_from_double(kSpecial[which % (sizeof kSpecial / sizeof *kSpecial)]);
}

SCM number(Recipe& in) {
    switch (in.byte() % 10) {
        case 0: return scm_from_int8(static_cast<int8_t>(in.byte()));
        case 1: return scm_from_int64(in.signed_word());  // a fixnum or, beyond 2^61, a bignum
        case 2: return scm_ash(scm_from_int64(in.signed_word() | 1), scm_from_int(62 + 4 * in.byte()));
        case 3: return scm_from_double(in.bits_as_double());
        case 4: return special_double(in.byte());
        case 5: {
            const int16_t num = static_cast<int16_t>(in.byte() << 8 | in.byte());
            const int16_t den = static_cast<int16_t>(in.byte() << 8 | in.byte());
            return scm_divide(scm_from_int16(num), scm_from_int16(den == 0 ? 3 : den));
        }
        case 6: return scm_from_double(static_cast<int16_t>(in.byte() << 8 | in.byte()) / 8.0);
        case 7: return scm_divide(scm_ash(scm_from_int8(1), scm_from_int(in.byte() * 8)), scm_from_int8(3));
        case 8: return scm_c_make_rectangular(in.byte() / 4.0, in.byte() / 4.0);
        default: return scm_from_int8(0);
    }
}

SCM value(Recipe& in, int depth);

// Ties the last pair of a list (or plist) to its end: () mostly, else an atom
// (a dotted tail) or, unless DS_FUZZ_CIRCULAR=0, one of the list's own pairs.
SCM close_list(Recipe& in, SCM head, SCM last, int length) {
    if (scm_is_false(last)) return head;
    const uint8_t how = in.byte() % 8;
    if (how == 6) scm_set_cdr_x(last, number(in));
    if (how == 7 && natives.circular) scm_set_cdr_x(last, scm_list_tail(head, scm_from_int(in.byte() % length)));
    return head;
}

// A list of values (symbols mostly, as #:skip-pipelines wants), built front to back.
SCM list_of(Recipe& in, int depth) {
    const int length = in.byte() % (kMaxListLength + 1);
    SCM head = SCM_EOL, last = SCM_BOOL_F;
    for (int i = 0; i < length; ++i) {
        SCM item = in.byte() % 4 ? scm_from_utf8_symbol(ds::skip_name(static_cast<uint16_t>(1u << (in.byte() % 9))))
                                 : value(in, depth + 1);
        SCM cell = scm_cons(item, SCM_EOL);
        if (scm_is_false(last)) head = cell;
        else scm_set_cdr_x(last, cell);
        last = cell;
    }
    return close_list(in, head, last, length);
}

SCM physics_key(Recipe& in) { return ds::guile::keys->key[in.byte() % ds::guile::kPhysKeyCount]; }

SCM value(Recipe& in, int depth) {
    switch (in.byte() % 9) {
        case 0: case 1: case 2: return number(in);
        case 3: return scm_from_bool(in.byte() & 1);
        case 4: {
            char text[8];
            const size_t length = in.byte() % sizeof text;
            for (size_t i = 0; i < length; ++i) text[i] = static_cast<char>(in.byte());
            return scm_from_latin1_stringn(text, length);
        }
        case 5: return in.byte() & 1 ? scm_from_utf8_symbol("swept") : scm_from_utf8_symbol("gravity");
        case 6: return depth < kMaxDepth ? list_of(in, depth) : SCM_EOL;
        case 7: return physics_key(in);
        default: return scm_from_utf8_keyword("unknown");
    }
}

SCM key(Recipe& in) {
    switch (in.byte() % 8) {
        case 5: return scm_from_utf8_keyword(in.byte() & 1 ? "unknown" : "name");
        case 6: return value(in, kMaxDepth);  // rarely a keyword: a malformed plist
        default: return physics_key(in);
    }
}

// A plist: key/value pairs, sometimes a key without a value at the end.
SCM plist(Recipe& in) {
    const int pairs = in.byte() % (kMaxPairs + 1);
    SCM head = SCM_EOL, last = SCM_BOOL_F;
    for (int i = 0; i < pairs; ++i) {
        SCM k = key(in);
        SCM cell = scm_list_2(k, value(in, 0));
        if (scm_is_false(last)) head = cell;
        else scm_set_cdr_x(last, cell);
        last = SCM_CDR(cell);
    }
    if (pairs > 0 && in.byte() % 8 == 0) {
        scm_set_cdr_x(last, scm_list_1(key(in)));
        return head;
    }
    return close_list(in, head, last, 2 * pairs);
}

// Decodes each entity of the list's proper prefix directly, as the steps do.
void decode_each(SCM entities) {
    int i = 0;
    for (SCM p = entities; scm_is_pair(p) && i < kMaxEntities; p = SCM_CDR(p), ++i) {
        ds::guile::Decoded d;
        ds::guile::Failure f{"fuzz"};
        if (ds::guile::decode_entity(SCM_CAR(p), d, f)) (void)ds::guile::watched_fields(d);
    }
}

struct Call {
    SCM proc;
    SCM args;
};

SCM apply_call(void* data) {
    const Call& c = *static_cast<const Call*>(data);
    return scm_apply_0(c.proc, c.args);
}
SCM refused(void*, SCM, SCM) { return SCM_BOOL_F; }

// Calls proc on args; a Scheme error is caught and gives #f.
SCM call(SCM proc, SCM args) {
    Call c{proc, args};
    return scm_c_catch(SCM_BOOL_T, apply_call, &c, refused, nullptr, nullptr, nullptr);
}

bool env_is(const char* name, const char* wanted) {
    const char* v = std::getenv(name);
    return v && std::strcmp(v, wanted) == 0;
}

// Writes `what`: value (cycles as datum labels) to stdout.
void show(const char* what, SCM value) {
    SCM port = scm_current_output_port();
    scm_display(scm_from_utf8_string(what), port);
    scm_display(scm_from_utf8_string(": "), port);
    scm_write(value, port);
    scm_newline(port);
    scm_force_output(port);
}

SCM some_tilemap(Recipe& in) {
    switch (in.byte() % 4) {
        case 0: return SCM_BOOL_F;
        case 3: return number(in);  // not a tilemap at all
        default: return natives.tilemap;
    }
}

SCM some_mode(Recipe& in) {
    switch (in.byte() % 4) {
        case 0: return scm_from_utf8_symbol("discrete");
        case 3: return value(in, kMaxDepth);
        default: return scm_from_utf8_symbol("swept");
    }
}

// A whole frame, then the same frame on what it returned (the decoding cache
// and the settled-frame shortcut), then each step procedure on its own.
void run_steps(Recipe& in, SCM entities) {
    SCM map = some_tilemap(in), mode = some_mode(in);
    SCM dt = in.byte() % 4 ? scm_from_double(1000.0 / 60) : number(in);
    SCM substeps = in.byte() % 4 ? scm_from_int(1 + in.byte() % 4) : number(in);
    SCM args = scm_list_5(entities, map, dt, mode, substeps);
    SCM stepped = call(natives.step_entities, args);
    if (natives.show) show("frame", scm_list_2(scm_cdr(args), stepped));
    if (scm_is_true(stepped))
        call(natives.step_entities, scm_list_5(stepped, map, dt, mode, substeps));
    for (SCM proc : natives.list_steps) call(proc, scm_list_1(entities));
    int i = 0;
    for (SCM p = entities; scm_is_pair(p) && i < kMaxEntities; p = SCM_CDR(p), ++i) {
        SCM e = SCM_CAR(p);
        for (SCM proc : natives.single) call(proc, scm_list_1(e));
        for (SCM proc : natives.tile_steps) call(proc, scm_list_3(e, map, mode));
        call(natives.detect_on_solid, scm_list_3(e, map, entities));
    }
}

SCM entity_list(Recipe& in) {
    const int count = 1 + in.byte() % kMaxEntities;
    SCM head = SCM_EOL, last = SCM_BOOL_F;
    for (int i = 0; i < count; ++i) {
        SCM cell = scm_cons(plist(in), SCM_EOL);
        if (scm_is_false(last)) head = cell;
        else scm_set_cdr_x(last, cell);
        last = cell;
    }
    return close_list(in, head, last, count);
}

SCM native(SCM module, const char* name) { return scm_variable_ref(scm_c_module_lookup(module, name)); }

void define_natives(void*) { ds_init_native(); }

SCM make_tilemap(SCM module) {
    SCM cells = scm_c_make_vector(32, scm_from_int(0));
    for (size_t i = 24; i < 32; ++i) scm_c_vector_set_x(cells, i, scm_from_int(1));
    SCM make = native(module, "make-tilemap");
    return scm_permanent_object(scm_call_6(make, scm_from_int(8), scm_from_int(4), scm_from_int(16),
                                           scm_from_int(16), cells, scm_list_1(scm_from_int(1))));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    scm_init_guile();
    SCM m = scm_c_define_module("downstroke native", define_natives, nullptr);
    natives.step_entities = native(m, "%step-entities");
    const char* single[] = {"%apply-acceleration", "%apply-gravity", "%apply-velocity-x", "%apply-velocity-y",
                            "%apply-velocity"};
    for (int i = 0; i < 5; ++i) natives.single[i] = native(m, single[i]);
    natives.tile_steps[0] = native(m, "%resolve-tile-collisions-x");
    natives.tile_steps[1] = native(m, "%resolve-tile-collisions-y");
    natives.detect_on_solid = native(m, "%detect-on-solid");
    natives.list_steps[0] = native(m, "resolve-entity-collisions");
    natives.list_steps[1] = native(m, "sync-groups");
    natives.list_steps[2] = native(m, "%scene-hash-entities");
    natives.tilemap = make_tilemap(m);
    natives.circular = !env_is("DS_FUZZ_CIRCULAR", "0");
    natives.show = env_is("DS_FUZZ_SHOW", "1");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Recipe in{data, size};
    SCM entities = entity_list(in);
    if (natives.show) show("entities", entities);
    decode_each(entities);
    run_steps(in, entities);
    scm_remember_upto_here_1(entities);
    return 0;
}
