#include "registry.hpp"

#include "keys.hpp"

namespace ds::guile {

void detail::define_gsubr(const char* name, int req, int opt, int rest, scm_t_subr fn, const char* doc) {
    SCM proc = scm_c_define_gsubr(name, req, opt, rest, fn);
    scm_set_procedure_property_x(proc, scm_from_utf8_symbol("documentation"), scm_from_utf8_string(doc));
    scm_c_export(name, nullptr);
}

}  // namespace ds::guile

// The entry point load-extension calls from (downstroke native).
extern "C" void ds_init_native() {
    using namespace ds::guile;
    init_keys();
    register_entity_procedures();
    register_tilemap_procedures();
    register_tween_procedures();
    register_frame_procedures();
    register_hash_procedures();
    register_gc_procedures();
    register_render_procedures();
    apply_gc_policy();
}
