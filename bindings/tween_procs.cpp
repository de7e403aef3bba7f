// SPDX-License-Identifier: MIT
// Tweens as Scheme records (defined in (downstroke tween)) stepped natively.
// Record fields, in order: props ((key start . end) …), duration, delay,
// ease (symbol or procedure), ease-index (or #f), repeat, yoyo?,
// on-complete, elapsed. They are read by position; %register-tween-type!
// checks the record type's field names against kTweenFieldNames.
#include <cmath>
#include <iterator>

#include "args.hpp"
#include "ease.hpp"
#include "keys.hpp"
#include "plist.hpp"
#include "registry.hpp"
#include "scm_number.hpp"
#include "tween.hpp"
#include "tween_step.hpp"

namespace ds::guile {

namespace {

enum TweenField { kProps, kDuration, kDelay, kEase, kEaseIndex, kRepeat, kYoyo, kOnComplete, kElapsed, kTweenFields };
// The <tween> record's field names, by TweenField.
constexpr const char* kTweenFieldNames[] = {"props",  "duration", "delay",       "ease",   "ease-index",
                                            "repeat", "yoyo?",    "on-complete", "elapsed"};
static_assert(std::size(kTweenFieldNames) == kTweenFields);

SCM tween_rtd = SCM_BOOL_F;

bool is_tween(SCM obj) {
    return scm_is_true(tween_rtd) && SCM_STRUCTP(obj) && scm_is_eq(SCM_STRUCT_VTABLE(obj), tween_rtd);
}

SCM field(SCM tween, TweenField i) { return SCM_STRUCT_SLOT_REF(tween, i); }

double real_field(SCM tween, TweenField i) { return scm_to_double(field(tween, i)); }

// A copy of the tween with a new elapsed time.
SCM with_elapsed(SCM tween, double elapsed) {
    SCM init = scm_list_1(scm_from_double(elapsed));
    for (int i = kElapsed - 1; i >= 0; --i) init = scm_cons(field(tween, static_cast<TweenField>(i)), init);
    return scm_make_struct_no_tail(tween_rtd, init);
}

// The tween's easing at t. A procedure is called as Scheme: the caller's
// frames must survive a longjmp (advance_entity_tween asserts its own).
double eased(SCM tween, double t, Failure& f) {
    SCM index = field(tween, kEaseIndex);
    if (scm_is_true(index)) return ease(static_cast<Ease>(scm_to_int(index)), t);
    SCM v = scm_call_1(field(tween, kEase), scm_from_double(t));  // a user's easing
    Num n;
    if (num_from_scm(v, n) != NumCheck::Ok) {
        fail(f, "wrong-type-arg", scm_list_2(field(tween, kEase), v), "tween easing ~S returned ~S, not a finite number");
        return 0;
    }
    return n.v;
}

SCM ease_index(SCM name) {
    if (!scm_is_symbol(name)) return SCM_BOOL_F;
    char* s = scm_to_utf8_string(scm_symbol_to_string(name));
    Ease e;
    const bool ok = ease_from_name(s, e);
    free(s);
    return ok ? scm_from_int(static_cast<int>(e)) : SCM_BOOL_F;
}

SCM ease_value(SCM index, SCM t) {
    Failure f{"ease"};
    Num n;
    if (!scm_is_signed_integer(index, 0, static_cast<int>(Ease::Custom) - 1) || num_from_scm(t, n) != NumCheck::Ok) {
        fail(f, "wrong-type-arg", scm_list_2(index, t), "expected an easing index and a real t, got ~S ~S");
        raise(f);
    }
    return scm_from_double(ease(static_cast<Ease>(scm_to_int(index)), n.v));
}

// Refuses a record type whose fields are not, by name and in order, those
// the stepper reads by position: a field added, dropped or moved in
// (downstroke tween) without TweenField would otherwise be read as another.
SCM register_tween_type(SCM rtd) {
    Failure f{"%register-tween-type!"};
    SCM expected = SCM_EOL;
    for (int i = kTweenFields - 1; i >= 0; --i) expected = scm_cons(scm_from_utf8_symbol(kTweenFieldNames[i]), expected);
    if (scm_is_false(scm_call_1(scm_c_public_ref("guile", "record-type?"), rtd))) {
        fail(f, "wrong-type-arg", scm_list_1(rtd), "expected the <tween> record type, got ~S");
    } else {
        SCM fields = scm_call_1(scm_c_public_ref("guile", "record-type-fields"), rtd);
        if (scm_is_false(scm_equal_p(fields, expected)))
            fail(f, "misc-error", scm_list_3(rtd, fields, expected),
                 "~S has the fields ~S, but the native tween stepper (TweenField in "
                 "bindings/tween_procs.cpp) reads ~S by position: the two must match");
    }
    if (f) raise(f);
    tween_rtd = scm_gc_protect_object(rtd);
    return SCM_UNSPECIFIED;
}

// What on-complete returned looks like an entity (a keyword first): it
// replaces the entity only if it is a whole one, so that a circular or
// improper list is refused here, naming on-complete, rather than later.
bool completed_entity(SCM r, Failure& f) {
    Failure bad{f.proc};
    Decoded check;
    if (decode_entity(r, check, bad)) return true;
    fail(f, bad.key, bad.irritants, "tween on-complete returned a bad entity: %s", bad.message);
    return false;
}

SCM step_tweens_1(SCM entity, SCM dt) {
    Failure f{"step-tweens"};
    double d = 0;
    SCM result = entity;
    static_assert(survives_longjmp<decltype(d), decltype(result)>);  // across advance_entity_tween's callbacks
    if (dt_from_scm(dt, d, f)) guarded(f, nullptr, [&] { result = advance_entity_tween(entity, d, f); });
    if (f) raise(f);
    return result;
}

}  // namespace

SCM advance_entity_tween(SCM entity, double dt, Failure& f) {
    Decoded d;
    if (!decode_entity(entity, d, f)) return entity;
    if (scm_is_false(d.tween) || d.body.skips(kSkipTweens)) return entity;
    SCM tween = d.tween;
    if (!is_tween(tween)) {
        fail(f, "wrong-type-arg", scm_list_2(keys->key[kTween], tween), "entity key ~S: expected a tween (make-tween), got ~S");
        return entity;
    }
    const double elapsed = real_field(tween, kElapsed) + dt;
    const TweenTiming timing{real_field(tween, kDuration), real_field(tween, kDelay),
                             scm_to_int64(field(tween, kRepeat)), scm_is_true(field(tween, kYoyo))};
    const TweenPhase phase = tween_phase(timing, elapsed);
    Edit edits[kMaxTweenProps + 1];
    size_t n = 0;
    // A custom easing (in eased) and on-complete are Scheme code run from
    // here: an error or escape in either longjmps over this frame.
    static_assert(survives_longjmp<decltype(d), decltype(elapsed), decltype(timing), decltype(phase),
                                   decltype(edits), decltype(n)>);
    if (phase.started) {
        const double e = eased(tween, phase.t, f);
        if (f) return entity;
        for (SCM p = field(tween, kProps); scm_is_pair(p) && n < kMaxTweenProps; p = SCM_CDR(p)) {
            SCM prop = SCM_CAR(p);  // (key start . end), checked by make-tween
            TweenProp tp;
            num_from_scm(SCM_CADR(prop), tp.start);
            num_from_scm(SCM_CDDR(prop), tp.end);
            edits[n++] = {SCM_CAR(prop), num_to_scm(tween_value(tp, phase, e))};
        }
    }
    edits[n++] = phase.finished ? Edit{keys->key[kTween], SCM_BOOL_F, true}
                                : Edit{keys->key[kTween], with_elapsed(tween, elapsed)};
    SCM result = rewrite_plist(entity, edits, n);
    SCM on_complete = field(tween, kOnComplete);
    if (phase.finished && scm_is_true(scm_procedure_p(on_complete))) {
        SCM r = scm_call_1(on_complete, result);
        if (scm_is_pair(r) && scm_is_keyword(SCM_CAR(r))) {
            if (!completed_entity(r, f)) return entity;
            result = r;
        }
    }
    return result;
}

void register_tween_procedures() {
    define_procedure<1, 0, 0, register_tween_type>("%register-tween-type!",
        "Tell the native side which record type tweens are; a record type whose fields are not "
        "(props duration delay ease ease-index repeat yoyo? on-complete elapsed), the ones it reads "
        "by position, is refused.");
    define_procedure<1, 0, 0, ease_index>("%ease-index",
        "The native index of an easing name such as 'quad-in-out, or #f.");
    define_procedure<2, 0, 0, ease_value>("%ease", WrapperDoc{"(index t)", "ease", "(downstroke tween)"});
    define_procedure<2, 0, 0, step_tweens_1>("%step-tweens",
        WrapperDoc{"(entity dt)", "step-tweens", "(downstroke physics)"});
}

}  // namespace ds::guile
