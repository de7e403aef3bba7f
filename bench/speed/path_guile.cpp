// SPDX-License-Identifier: MIT
// The guile and reference paths: Guile booted in this process (as the
// downstroke host does it), the scene built as keyword-plist entities, and
// the frames stepped by (bench driver)'s run-frames: a Scheme loop that
// times each (step-scene scene dt) with get-internal-real-time and counts
// the bytes allocated inside that bracket with (gc-stats).
#include <libguile.h>

#include <algorithm>
#include <cstdlib>

#include "common/guile_boot.hpp"
#include "common/timing.hpp"
#include "speed/paths.hpp"

namespace bench {

namespace {

SCM kw(const char* name) { return scm_from_utf8_keyword(name); }
SCM num(int64_t v) { return scm_from_int64(v); }

SCM entity(const SceneBody& b, bool bounce) {
    SCM tail = SCM_EOL;
    if (bounce) tail = scm_list_4(kw("rvx"), num(b.rvx), kw("rvy"), num(b.rvy));
    if (b.enemy)
        tail = scm_cons_star(kw("category"), scm_list_4(scm_from_utf8_symbol("enemy"), kw("collides-with"),
                                                        scm_list_2(scm_from_utf8_symbol("enemy"),
                                                                   scm_from_utf8_symbol("default")),
                                                        tail));
    auto sym = [](const char* name) { return scm_from_utf8_symbol(name); };
    if (b.target)
        tail = scm_cons_star(kw("category"), scm_list_4(sym("enemy"), kw("collides-with"),
                                                        scm_list_3(sym("enemy"), sym("default"), sym("shot")), tail));
    if (b.shot)
        tail = scm_cons_star(kw("category"),
                             scm_list_4(sym("shot"), kw("collides-with"), scm_list_1(sym("enemy")), tail));
    if (b.bounce) tail = scm_cons_star(kw("bounce"), scm_list_2(num(1), tail));
    if (b.sensor) tail = scm_cons_star(kw("sensor?"), scm_list_2(SCM_BOOL_T, tail));
    if (b.contacts) tail = scm_cons_star(kw("contacts?"), scm_list_2(SCM_BOOL_T, tail));
    // The game's own keys, where an author writes them: after the engine's,
    // or (author_first) before.
    const SCM author = b.author_keys ? scm_list_n(kw("kind"), sym("shot"), kw("damage"), num(1), kw("owner"),
                                                  sym("player"), kw("ttl"), num(600), SCM_UNDEFINED)
                                     : SCM_EOL;
    if (b.knobs)
        tail = scm_cons_star(kw("gravity-scale"),
                             scm_list_n(num(2), kw("drag"), num(1), kw("max-vx"), num(4), kw("max-vy"), num(64),
                                        tail, SCM_UNDEFINED));
    if (!b.author_first) tail = scm_append(scm_list_2(tail, author));
    SCM head = scm_list_n(kw("type"), scm_from_utf8_symbol(b.immovable ? "pillar" : "box"),
                          kw("x"), num(b.x), kw("y"), num(b.y), kw("width"), num(b.w),
                          kw("height"), num(b.h), kw("vx"), num(b.vx), kw("vy"), num(b.vy),
                          kw("gravity?"), scm_from_bool(b.gravity), kw("on-ground?"),
                          scm_from_bool(b.on_ground), kw("solid?"), scm_from_bool(b.solid),
                          kw("immovable?"), scm_from_bool(b.immovable), SCM_UNDEFINED);
    return b.author_first ? scm_append(scm_list_3(author, head, tail)) : scm_append(scm_list_2(head, tail));
}

SCM tilemap(const Scene& s) {
    if (!s.map_path.empty())
        return scm_call_1(scm_c_public_ref("downstroke tilemap", "load-tilemap"),
                          scm_from_utf8_string(s.map_path.c_str()));
    SCM cells = scm_c_make_vector(s.solid.size(), scm_from_int(0));
    for (size_t i = 0; i < s.solid.size(); ++i)
        if (s.solid[i]) scm_c_vector_set_x(cells, i, scm_from_int(1));
    // Shaped cells: their gid, and (gid . (polygon (x . y) …)) once per gid.
    SCM shapes = SCM_EOL;
    std::vector<int> seen;
    for (const SceneShape& sh : s.shapes) {
        scm_c_vector_set_x(cells, static_cast<size_t>(sh.row) * s.cols + sh.col, scm_from_int(sh.gid));
        if (std::find(seen.begin(), seen.end(), sh.gid) != seen.end()) continue;
        seen.push_back(sh.gid);
        SCM pts = SCM_EOL;
        for (auto it = sh.polygon.rbegin(); it != sh.polygon.rend(); ++it)
            pts = scm_cons(scm_cons(scm_from_int(it->first), scm_from_int(it->second)), pts);
        shapes = scm_cons(scm_cons(scm_from_int(sh.gid), scm_cons(scm_from_utf8_symbol("polygon"), pts)), shapes);
    }
    SCM args = scm_list_n(scm_from_int(s.cols), scm_from_int(s.rows), scm_from_int(s.tile),
                          scm_from_int(s.tile), cells, shapes, SCM_UNDEFINED);
    return scm_apply_0(scm_c_public_ref("bench driver", "grid-tilemap"), args);
}

SCM plist_ref(SCM plist, SCM key) {
    for (SCM p = plist; scm_is_pair(p) && scm_is_pair(SCM_CDR(p)); p = SCM_CDR(SCM_CDR(p)))
        if (scm_is_eq(SCM_CAR(p), key)) return SCM_CAR(SCM_CDR(p));
    return SCM_BOOL_F;
}

struct Job {
    const Scene* scene;
    RunConfig cfg;
    bool reference;
    PathResult* out;
};

SCM run_job(void* data) {
    Job& job = *static_cast<Job*>(data);
    const Scene& s = *job.scene;
    const int64_t t_setup = now_ns();
    SCM entities = SCM_EOL;
    for (auto b = s.bodies.rbegin(); b != s.bodies.rend(); ++b) entities = scm_cons(entity(*b, s.bounce), entities);
    SCM scene = scm_call_2(scm_c_public_ref("bench driver", "make-bench-scene"), entities, tilemap(s));
    SCM step = scm_c_public_ref(job.reference ? "downstroke reference" : "downstroke physics", "step-scene");
    job.out->setup_ms = static_cast<double>(now_ns() - t_setup) / 1e6;
    const double budget_ns = std::min(job.cfg.budget_ms * 1e6, 1e18);
    SCM args = scm_list_n(step, scene, scm_from_double(1000.0 / 60.0), scm_from_int(job.cfg.warmup),
                          scm_from_int(job.cfg.frames), scm_from_bool(s.bounce),
                          scm_from_int64(static_cast<int64_t>(job.cfg.max_frame_ms * 1e6)),
                          scm_from_int64(static_cast<int64_t>(budget_ns)), scm_from_bool(!job.reference),
                          SCM_UNDEFINED);
    // A scene with resting contacts runs under (parameterize ((resting-contacts? #t)) …).
    SCM run_frames = scm_c_public_ref("bench driver", "run-frames");
    if (s.resting_contacts)
        run_frames = scm_call_1(scm_c_eval_string("(lambda (run) (lambda args (parameterize "
                                                  "(((@ (downstroke physics) resting-contacts?) #t)) "
                                                  "(apply run args))))"),
                                run_frames);
    SCM result = scm_apply_0(run_frames, args);
    SCM times = scm_car(result);
    const double bytes = scm_to_double(scm_cadr(result));
    const double overhead = scm_to_double(scm_caddr(result));
    const size_t frames = scm_c_vector_length(times);
    SCM too_slow_ns = scm_list_ref(result, scm_from_int(4));
    if (scm_is_true(too_slow_ns)) job.out->skipped = too_slow(scm_to_double(too_slow_ns) / 1e6, job.cfg.max_frame_ms);
    job.out->spent_ms = scm_to_double(scm_list_ref(result, scm_from_int(5))) / 1e6;
    job.out->gc_ms = scm_to_double(scm_list_ref(result, scm_from_int(6))) / 1e6;
    SCM split = scm_list_ref(result, scm_from_int(7));
    if (scm_is_vector(split)) {
        auto at = [&](size_t i) { return scm_to_double(scm_c_vector_ref(split, i)); };
        job.out->split = {static_cast<int>(frames), at(0), at(1), at(2), at(3), at(4), at(5), at(6)};
    }
    for (size_t i = 0; i < frames; ++i)
        job.out->frame_ms.push_back(scm_to_double(scm_c_vector_ref(times, i)) / 1e6);
    job.out->checksum = 0;
    SCM x = kw("x"), y = kw("y"), type = kw("type"), pillar = scm_from_utf8_symbol("pillar");
    for (SCM p = scm_call_1(scm_c_public_ref("bench driver", "bench-scene-entities"), scm_cadddr(result));
         scm_is_pair(p); p = SCM_CDR(p)) {
        SCM e = SCM_CAR(p);
        if (scm_is_eq(plist_ref(e, type), pillar)) continue;
        job.out->checksum += scm_to_double(plist_ref(e, x)) + 3 * scm_to_double(plist_ref(e, y));
    }
    if (frames > 0) {
        const double per_frame = bytes / static_cast<double>(frames) - overhead;
        job.out->bytes_per_frame = per_frame > 0 ? per_frame : 0;
    }
    return SCM_BOOL_T;
}

SCM on_error(void* data, SCM key, SCM args) {
    Job& job = *static_cast<Job*>(data);
    job.out->error = error_text(key, args);
    job.out->frame_ms.clear();
    return SCM_BOOL_F;
}

void* run_in_guile(void* data) {
    scm_c_catch(SCM_BOOL_T, run_job, data, on_error, data, nullptr, nullptr);
    return nullptr;
}

}  // namespace

PathResult run_guile(const Scene& scene, const RunConfig& cfg, bool reference) {
    ensure_guile();
    PathResult r;
    Job job{&scene, cfg, reference, &r};
    scm_with_guile(run_in_guile, &job);
    return r;
}

}  // namespace bench
