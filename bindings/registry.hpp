// SPDX-License-Identifier: MIT
// Each native procedure is registered next to its definition, with its
// docstring, into the module being initialised (downstroke native):
//
//     define_procedure<1, 0, 0, apply_gravity_1>("%apply-gravity", doc);
//
// Each public procedure's docstring is in one place. A procedure exported
// from (downstroke native) under its public name (make-tilemap, sync-groups)
// has it here. The native code of a public Scheme procedure (apply-gravity
// calls %apply-gravity) gets a WrapperDoc instead, which only gives the
// native argument list and names the wrapper, whose docstring is the one.
// The building blocks no public docstring describes (%make-display,
// %display-poll!, …) document their own interface here.
//
// The template checks the counts against the C++ signature when it compiles
// (LilyPond's ly_subr_ptr idea): every parameter and the result are SCM, and
// req + opt + rest is the parameter count, so a wrong count does not build.
//
// What Guile calls is a trampoline around fn: a C++ exception that fn lets
// escape becomes a Scheme error naming the procedure, raised once the
// exception object is gone, so none ever unwinds into Guile's C frames
// (which aborts the process). The procedures still run their C++ work in
// guarded() (failure.hpp), for a message naming the public procedure and so
// that their own cleanup (scm_dynwind_end) runs; the trampoline is the net
// under every one of them, including any that forgets.
#pragma once
#include <libguile.h>

#include <type_traits>

#include "failure.hpp"

namespace ds::guile {

// The docstring of the native code of a public Scheme procedure:
// "ARGS: native code for NAME in MODULE, which documents it."
struct WrapperDoc {
    const char* args;    // the native argument list, "(entity tilemap mode)"
    const char* name;    // the public procedure, "resolve-tile-collisions-x"
    const char* module;  // where it is defined, "(downstroke physics)"
};

namespace detail {

template <class F>
struct Signature {
    static constexpr bool scm_only = false;
    static constexpr int arity = -1;
    using Plain = void;
};
template <class... A>
struct Signature<SCM (*)(A...)> {
    static constexpr bool scm_only = (std::is_same_v<A, SCM> && ...);
    static constexpr int arity = sizeof...(A);
    using Plain = SCM (*)(A...);
};
template <class... A>
struct Signature<SCM (*)(A...) noexcept> : Signature<SCM (*)(A...)> {};

// The name each function was registered under, for the trampoline's message.
template <auto Fn>
inline const char* name_of = nullptr;

// Called in the trampoline's catch handler: records the exception being
// handled (its what()) as this thread's escaped failure. raise_escaped then
// raises it, after the handler has ended: a longjmp out of a handler would
// leave the exception object allocated and the runtime's handler count off.
void note_escaped(const char* proc) noexcept;
[[noreturn]] void raise_escaped();

// Only SCM values (and nothing with a destructor) live in this frame, so a
// Scheme error raised inside fn may longjmp straight over it.
template <auto Fn, class... A>
SCM trampoline(A... args) {
    try {
        return Fn(args...);
    } catch (...) {
        note_escaped(name_of<Fn>);
    }
    raise_escaped();
}

// The trampoline for Fn, deduced from Fn's type alone: fn's address is
// taken nowhere else, so the compiler may inline fn into its trampoline.
template <auto Fn, class... A>
scm_t_subr subr_of(std::type_identity<SCM (*)(A...)>) {
    return reinterpret_cast<scm_t_subr>(&trampoline<Fn, A...>);
}

// Refuses (when the extension loads) a function registered under a second
// name: its trampoline would report the first.
void check_one_name(const char*& registered, const char* name);

void define_gsubr(const char* name, int req, int opt, int rest, scm_t_subr fn, const char* doc);
void define_gsubr(const char* name, int req, int opt, int rest, scm_t_subr fn, const WrapperDoc& doc);

}  // namespace detail

// Defines and exports `name`, taking Req required, Opt optional and (Rest 1)
// a rest argument, with its docstring (a string, or a WrapperDoc).
template <int Req, int Opt, int Rest, auto Fn, class Doc>
void define_procedure(const char* name, const Doc& doc) {
    using Sig = detail::Signature<std::remove_cvref_t<decltype(Fn)>>;
    static_assert(Sig::scm_only, "a native procedure takes SCM arguments and returns SCM");
    static_assert(Req >= 0 && Opt >= 0 && (Rest == 0 || Rest == 1), "req, opt ≥ 0 and rest 0 or 1");
    static_assert(Req + Opt + Rest == Sig::arity,
                  "req + opt + rest must be the number of the C++ function's parameters");
    static_assert(Sig::arity <= SCM_GSUBR_MAX, "Guile's subrs take at most SCM_GSUBR_MAX arguments");
    detail::check_one_name(detail::name_of<Fn>, name);
    detail::define_gsubr(name, Req, Opt, Rest, detail::subr_of<Fn>(std::type_identity<typename Sig::Plain>{}), doc);
}

// The renderer's procedures are declared in tables (render/*.def), one row
// each, because two builds read them: with SDL2 the file of the same name
// registers every row; without it render_missing.cpp registers a stand-in
// for each procedure that needs the renderer. A row is
//
//     DS_RENDER_NATIVE("%make-display", 2, 0, 0, make_display, "(width height): …")
//
// name, required, optional and rest (0 or 1) argument counts, the C++
// function, and its docstring (a string or a WrapperDoc), as
// define_procedure takes them. DS_RENDER_NATIVE marks a procedure that needs
// the renderer; DS_NATIVE one that every build has (then render_missing.cpp
// defines a C++ function of the same name: %renderer? answers #f there).
// Registering a row is DS_DEFINE_NATIVE:
#define DS_DEFINE_NATIVE(name, req, opt, rest, fn, ...) \
    ::ds::guile::define_procedure<req, opt, rest, fn>(name, __VA_ARGS__);

// Each file of procedures has one of these; ds_init_native (registry.cpp)
// calls them all.
void register_entity_procedures();
void register_tilemap_procedures();
void register_tween_procedures();
void register_frame_procedures();
void register_hash_procedures();
void register_gc_procedures();
void register_query_procedures();  // spatial and tile queries
void register_key_slip_procedures();  // misspelt entity keys (key_slips.hpp)
void register_constants();  // the rules' numbers: %gravity, %jump-force, …
void register_render_procedures();  // render/display.cpp, or render_missing.cpp without SDL2

// The engine's collector setting (gc_procs.cpp), applied when the extension loads.
void apply_gc_policy();

}  // namespace ds::guile
