// Each native procedure is registered next to its definition, with its
// docstring, into the module being initialised (downstroke native).
#pragma once
#include <libguile.h>

namespace ds::guile {

using Subr = scm_t_subr;

// Defines and exports `name` with its docstring.
void define_procedure(const char* name, int req, int opt, int rest, Subr fn, const char* doc);

// Each file of procedures has one of these; ds_init_native (registry.cpp)
// calls them all.
void register_entity_procedures();
void register_tilemap_procedures();
void register_tween_procedures();
void register_frame_procedures();
void register_hash_procedures();
void register_gc_procedures();
void register_constants();  // the rules' numbers: %gravity, %jump-force, …
void register_render_procedures();  // render_procs.cpp, or render_missing.cpp without SDL2

// The engine's collector setting (gc_procs.cpp), applied when the extension loads.
void apply_gc_policy();

}  // namespace ds::guile
