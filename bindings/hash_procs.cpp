// SPDX-License-Identifier: MIT
// scene-hash's native half: the physical state of an entity list, hashed
// by the core (state_hash.hpp) so that Scheme and C++ agree on the bytes.
#include "args.hpp"
#include "list_walk.hpp"
#include "plist.hpp"
#include "registry.hpp"
#include "state_hash.hpp"

namespace ds::guile {

namespace {

// Each plist is decoded as every physics step decodes it, so the hash sees
// exactly the state the steps see (first occurrence of a key wins, a
// missing key is exact 0 or #f) and refuses what they refuse.
SCM scene_hash_entities(SCM entities, SCM gravity) {
    Failure f{"scene-hash"};
    uint64_t hash = 0;
    guarded(f, nullptr, [&] {
        StateHash h;
        Decoded d;
        SCM p = entities;
        Tortoise tortoise;
        for (; scm_is_pair(p) && !f; p = SCM_CDR(p))
            if (tortoise.caught(p)) fail_circular(f, "entities", "a list of entities", entities);
            else if (decode_entity(SCM_CAR(p), d, f)) h.add(d.body);
        if (!f && !scm_is_null(p))
            fail(f, "wrong-type-arg", scm_list_1(entities), "expected a list of entities, got ~S");
        Num g;
        if (!f && gravity_from_scm(gravity, g, f)) h.add_gravity(g);
        hash = h.value();
    });
    if (f) raise(f);
    return scm_from_uint64(hash);
}

}  // namespace

void register_hash_procedures() {
    define_procedure<1, 1, 0, scene_hash_entities>("%scene-hash-entities",
        WrapperDoc{"(entities [gravity])", "scene-hash", "(downstroke hash)"});
}

}  // namespace ds::guile
