// SPDX-License-Identifier: MIT
// The per-entity physics steps and the bulk steps as native procedures.
// Each: validate and decode → run the core step → encode only what changed.
#include <algorithm>
#include <cmath>

#include "args.hpp"
#include "batch.hpp"
#include "carry.hpp"
#include "contact_report.hpp"
#include "contacts.hpp"
#include "detail/contact_scratch.hpp"
#include "convert.hpp"
#include "groups.hpp"
#include "keys.hpp"
#include "plist.hpp"
#include "pushed_pairs.hpp"
#include "registry.hpp"
#include "steps.hpp"
#include "tilemap_type.hpp"
#include "ground.hpp"
#include "tiles.hpp"

namespace ds::guile {

namespace {

// No #:standing-on to report (every step but detect-on-solid).
struct NoStanding {
    SCM operator()(const Body&) const { return SCM_UNDEFINED; }
};

// Decodes one entity, runs step on its body, encodes what changed; a
// contact entity's #:standing-on is named by `standing` (semantics §10).
// With `categories`, the entity's categories become bits in that table
// (a scene's it is compared with).
template <typename Step, typename Standing = NoStanding>
SCM step_entity(const char* proc, SCM entity, Step step, Standing standing = {},
                CategoryTable* categories = nullptr) {
    Failure f{proc};
    SCM result = entity;
    {
        Decoded d;
        if (decode_entity(entity, d, f) &&
            (!categories || categories->assign(d.category, d.collides_with, d.body, f))) {
            const Body before = d.body;
            guarded(f, nullptr, [&] { step(d.body); });
            Edit edits[kFieldCount + 2];
            const uint32_t changed = changed_fields(before, d.body);
            if (!f && check_finite(d.body, changed, f)) {
                size_t n = field_edits(changed, d.body, edits);
                if (d.body.contacts) n = report_edits(entity, SCM_UNDEFINED, standing(d.body), edits, n);
                result = rewrite_plist(entity, edits, n);
            }
        }
    }
    if (f) raise(f);
    return result;
}

SCM apply_acceleration_1(SCM e) { return step_entity("apply-acceleration", e, apply_acceleration); }
SCM apply_gravity_1(SCM e, SCM gravity) {
    Failure f{"apply-gravity"};
    Num g;
    if (!gravity_from_scm(gravity, g, f)) raise(f);
    return step_entity("apply-gravity", e, [g](Body& b) { return apply_gravity(b, SubStep{}, g); });
}
SCM apply_speed_limits_1(SCM e) {
    return step_entity("apply-speed-limits", e, [](Body& b) { return apply_speed_limits(b); });
}
SCM apply_velocity_x_1(SCM e) { return step_entity("apply-velocity-x", e, [](Body& b) { return apply_velocity_x(b); }); }
SCM apply_velocity_y_1(SCM e) { return step_entity("apply-velocity-y", e, [](Body& b) { return apply_velocity_y(b); }); }
SCM apply_velocity_1(SCM e) { return step_entity("apply-velocity", e, apply_velocity); }

template <bool (*Resolve)(Body&, const TileGrid*, CollisionMode, SubStep)>
SCM resolve_tiles(const char* proc, SCM e, SCM tilemap, SCM mode) {
    Failure f{proc};
    const TileGrid* grid = nullptr;
    CollisionMode m{};
    if (!grid_from_scm(tilemap, grid, f) || !mode_from_scm(mode, m, f)) raise(f);
    return step_entity(proc, e, [&](Body& b) { Resolve(b, grid, m, SubStep{}); });
}

SCM resolve_tile_x_1(SCM e, SCM tm, SCM mode) {
    return resolve_tiles<resolve_tile_collisions_x>("resolve-tile-collisions-x", e, tm, mode);
}
SCM resolve_tile_y_1(SCM e, SCM tm, SCM mode) {
    return resolve_tiles<resolve_tile_collisions_y>("resolve-tile-collisions-y", e, tm, mode);
}

// The scene's entities, decoded; every slot holding the entity itself (eq?)
// is left out as a supporter, as semantics §4 says "not eq?".
SCM detect_on_solid_1(SCM e, SCM tilemap, SCM entities) {
    Failure f{"detect-on-solid"};
    SCM result = e;
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    guarded(f, nullptr, [&] {
        const TileGrid* grid = nullptr;
        Batch& scene = lease_batch();
        CategoryTable categories;
        if (grid_from_scm(tilemap, grid, f) && decode_batch(entities, scene, f, &categories)) {
            size_t index = 0;
            for (SCM p = entities; scm_is_pair(p); p = SCM_CDR(p), ++index)
                if (scm_is_eq(SCM_CAR(p), e)) scene.bodies[index].solid = false;
            auto detect = [&](Body& b) {
                if (detect_on_solid(b, scene.bodies, -1, grid) && b.contacts)
                    b.standing_on = static_cast<int32_t>(first_supporter(b, scene.bodies, -1) + 1);
            };
            auto standing = [&](const Body& b) {
                if (!b.detects_ground()) return SCM_UNDEFINED;
                if (b.standing_on <= 0) return SCM_BOOL_F;
                const auto k = static_cast<size_t>(b.standing_on - 1);
                return entity_name(scm_list_ref(entities, scm_from_size_t(k)), k);
            };
            result = step_entity("detect-on-solid", e, detect, standing, &categories);
        }
    });
    scm_dynwind_end();
    if (f) raise(f);
    return result;
}

template <void (*Bulk)(Batch&)>
SCM bulk_step(const char* proc, SCM entities) {
    Failure f{proc};
    SCM result = entities;
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    guarded(f, nullptr, [&] {
        Batch& batch = lease_batch();
        if (decode_batch(entities, batch, f)) {
            Bulk(batch);
            result = encode_batch(entities, batch, f);
        }
    });
    scm_dynwind_end();
    if (f) raise(f);
    return result;
}

// Scheme's bulk push-apart has no Frame to own its scratch: it keeps one per
// thread here in the bindings (so a warm call does not allocate), and notes
// pairs in the overlay's log as step-scene does.
// With contact entities it logs the pairs (in the overlay's log when there
// is one) to write their #:touching from (semantics §10).
void resolve_noting_pairs(Batch& batch) {
    thread_local ContactScratch scratch;
    thread_local PairLog own;
    thread_local SideLog sides;
    const std::span<Body> bodies(batch.bodies);
    const bool reports = batch.contact_bodies != 0;
    PairLog* overlay = pushed_pairs();
    own.clear();
    PairLog* log = overlay ? overlay : reports ? &own : nullptr;
    const size_t from = log ? log->size() : 0;
    scratch.log = log;
    sides.clear();  // by the log's pairs from `from` on
    scratch.sides = &sides;
    resolve_entity_collisions(scratch, bodies);
    if (!reports) return;
    batch.contacts.gather(std::span<const IndexPair>(*log).subspan(from), sides, bodies);
    batch.reports = kReportsTouching;
}
// Groups need scratch only when some body has an origin: a local one will do.
void sync_groups_alone(Batch& batch) { sync_groups(batch.bodies); }

SCM resolve_entity_collisions_n(SCM entities) {
    return bulk_step<resolve_noting_pairs>("resolve-entity-collisions", entities);
}
SCM sync_groups_n(SCM entities) { return bulk_step<sync_groups_alone>("sync-groups", entities); }

// The carry step alone (semantics §11): `start` is the frame-start scene's
// entities, body for body the list before this frame's per-entity steps.
void carry_batch(Batch& now, Batch& then, const TileGrid* grid, CollisionMode mode) {
    thread_local std::vector<size_t> members, carriers;
    thread_local CarryScratch scratch;
    members.clear();
    carriers.clear();
    for (size_t i = 0; i < now.size(); ++i) {
        if (!now.bodies[i].collides()) continue;
        members.push_back(i);
        if (is_carrier(now.bodies[i])) carriers.push_back(i);
    }
    clear_crushed(now.bodies, members);
    carry_riders(now.bodies, then.bodies, carriers, members, grid, mode, scratch);
}

SCM carry_riders_n(SCM entities, SCM tilemap, SCM start, SCM mode) {
    Failure f{"carry-riders"};
    SCM result = entities;
    scm_dynwind_begin(static_cast<scm_t_dynwind_flags>(0));
    guarded(f, nullptr, [&] {
        const TileGrid* grid = nullptr;
        CollisionMode m{};
        Batch& now = lease_batch();
        Batch& then = lease_batch();
        CategoryTable categories;
        if (!grid_from_scm(tilemap, grid, f) || !mode_from_scm(mode, m, f) ||
            !decode_batch(entities, now, f, &categories) || !decode_batch(start, then, f, &categories))
            return;
        if (then.size() != now.size()) {
            fail(f, "wrong-type-arg", scm_list_2(scm_from_size_t(now.size()), scm_from_size_t(then.size())),
                 "expected the scene to hold as many entities as the list (~S), got ~S");
            return;
        }
        carry_batch(now, then, grid, m);
        result = encode_batch(entities, now, f);
    });
    scm_dynwind_end();
    if (f) raise(f);
    return result;
}

SCM aabb_overlap_p(SCM x1, SCM y1, SCM w1, SCM h1, SCM x2, SCM y2, SCM w2, SCM h2) {
    Failure f{"aabb-overlap?"};
    const SCM args[8] = {x1, y1, w1, h1, x2, y2, w2, h2};
    double v[8];
    for (int i = 0; i < 8; ++i)
        if (!from_scm(args[i], v[i], i + 1, f)) raise(f);
    return scm_from_bool(aabb_overlap(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
}

}  // namespace

void register_entity_procedures() {
    // The per-entity steps' docstrings are their wrappers' in (downstroke physics).
    constexpr const char* physics = "(downstroke physics)";
    define_procedure<1, 0, 0, apply_acceleration_1>("%apply-acceleration",
        WrapperDoc{"(entity)", "apply-acceleration", physics});
    define_procedure<1, 1, 0, apply_gravity_1>("%apply-gravity",
        WrapperDoc{"(entity [gravity])", "apply-gravity", physics});
    define_procedure<1, 0, 0, apply_speed_limits_1>("%apply-speed-limits",
        WrapperDoc{"(entity)", "apply-speed-limits", physics});
    define_procedure<1, 0, 0, apply_velocity_x_1>("%apply-velocity-x",
        WrapperDoc{"(entity)", "apply-velocity-x", physics});
    define_procedure<1, 0, 0, apply_velocity_y_1>("%apply-velocity-y",
        WrapperDoc{"(entity)", "apply-velocity-y", physics});
    define_procedure<1, 0, 0, apply_velocity_1>("%apply-velocity", WrapperDoc{"(entity)", "apply-velocity", physics});
    define_procedure<3, 0, 0, resolve_tile_x_1>("%resolve-tile-collisions-x",
        WrapperDoc{"(entity tilemap mode)", "resolve-tile-collisions-x", physics});
    define_procedure<3, 0, 0, resolve_tile_y_1>("%resolve-tile-collisions-y",
        WrapperDoc{"(entity tilemap mode)", "resolve-tile-collisions-y", physics});
    define_procedure<3, 0, 0, detect_on_solid_1>("%detect-on-solid",
        WrapperDoc{"(entity tilemap entities)", "detect-on-solid", physics});
    // Exported as they are (re-exported by (downstroke physics)): documented here.
    define_procedure<1, 0, 0, resolve_entity_collisions_n>("resolve-entity-collisions",
        "(resolve-entity-collisions entities): the list with overlapping solid entities pushed "
        "apart, one pass over the pairs in list order.");
    define_procedure<1, 0, 0, sync_groups_n>("sync-groups",
        "(sync-groups entities): the list with every group member placed at its origin's "
        "position plus its local offset.");
    define_procedure<4, 0, 0, carry_riders_n>("%carry-riders",
        WrapperDoc{"(entities tilemap start-entities mode)", "carry-riders", physics});
    define_procedure<8, 0, 0, aabb_overlap_p>("aabb-overlap?",
        "(aabb-overlap? x1 y1 w1 h1 x2 y2 w2 h2): strict overlap of two boxes.");
}

}  // namespace ds::guile
