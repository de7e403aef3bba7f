#include "tilemap_type.hpp"

#include <memory>
#include <string>

#include "convert.hpp"
#include "failure.hpp"
#include "list_walk.hpp"
#include "registry.hpp"
#include "tilemap_info.hpp"

namespace ds::guile {

namespace {

SCM tilemap_type = SCM_BOOL_F;

void finalize_tilemap(SCM obj) {
    delete static_cast<MapHandle*>(scm_foreign_object_ref(obj, 0));
    scm_foreign_object_set_x(obj, 0, nullptr);
}

SCM wrap(std::unique_ptr<MapHandle> handle) {
    return scm_make_foreign_object_1(tilemap_type, handle.release());
}

bool gid_list(SCM list, std::vector<uint32_t>& out, const char* what, Failure& f) {
    SCM p = list;
    Tortoise tortoise;
    for (; scm_is_pair(p); p = SCM_CDR(p)) {
        if (tortoise.caught(p)) {
            fail_circular(f, what, "a list of gids", list);
            return false;
        }
        SCM g = SCM_CAR(p);
        if (!scm_is_unsigned_integer(g, 0, kGidMask)) {
            fail(f, "wrong-type-arg", scm_list_2(g, list), "%s: expected gids (exact integers ≥ 0), got ~S in ~S", what);
            return false;
        }
        out.push_back(scm_to_uint32(g));
    }
    if (!scm_is_null(p)) {
        fail_arg(f, what, list, "a list of gids");
        return false;
    }
    return true;
}

// A MapLimits field from a keyword: #f keeps the default.
bool limit_arg(SCM v, const char* name, int64_t& out, Failure& f) {
    if (scm_is_false(v)) return true;
    if (scm_is_signed_integer(v, 1, INT64_MAX)) {
        out = scm_to_int64(v);
        return true;
    }
    fail_arg(f, name, v, "a positive exact integer or #f");
    return false;
}

// A path argument as a malloc'd UTF-8 copy (the caller frees it), or
// nullptr with a Failure.
char* path_arg(SCM v, const char* what, Failure& f) {
    if (scm_is_string(v)) return scm_to_utf8_string(v);
    fail_arg(f, what, v, "a file name");
    return nullptr;
}

SCM load_tilemap(SCM path, SCM solid_gids, SCM max_cells, SCM max_bytes, SCM strict, SCM project) {
    Failure f{"load-tilemap"};
    MapLimits limits;
    if (!limit_arg(max_cells, "max-cells", limits.max_cells, f) ||
        !limit_arg(max_bytes, "max-bytes", limits.max_bytes, f))
        raise(f);  // a wrong-type-arg; nothing is allocated yet
    if (!scm_is_bool(strict)) {
        fail_arg(f, "strict?", strict, "#t or #f");
        raise(f);
    }
    SCM result = SCM_BOOL_F;
    if (!scm_is_string(path)) {
        fail(f, "wrong-type-arg", scm_list_1(path), "expected a file name, got ~S");
        raise(f);
    }
    char* cproject = scm_is_false(project) ? nullptr : path_arg(project, "project", f);
    if (f) raise(f);
    char* cpath = scm_to_utf8_string(path);  // both freed below, before any raise
    {
        std::unique_ptr<MapHandle> handle;
        guarded(f, nullptr, [&] {
            LoadOptions options;
            if (!gid_list(solid_gids, options.solid_gids, "solid-gids", f)) return;
            options.limits = limits;
            options.strict = scm_is_true(strict);
            if (cproject) options.project_path = cproject;
            handle = std::make_unique<MapHandle>();
            handle->map = ds::load_tilemap(cpath, options);
            handle->grid = handle->map.solid_grid();
        });
        if (handle) result = wrap(std::move(handle));
    }
    free(cpath);
    free(cproject);
    if (f) {
        f.key = "misc-error";  // printed as "In procedure load-tilemap: <file>:<line>: …"
        raise(f);
    }
    return result;
}

bool positive_int(SCM v, const char* what, int& out, Failure& f) {
    // The range an int holds safely; map_size_problem then applies the map limits.
    return from_scm(v, out, what, f, 1, 1 << 24, "a positive exact integer");
}

SCM make_tilemap(SCM width, SCM height, SCM tile_w, SCM tile_h, SCM cells, SCM solid_gids, SCM one_way_gids) {
    Failure f{"make-tilemap"};
    SCM result = SCM_BOOL_F;
    {
        int w = 0, h = 0, tw = 0, th = 0;
        std::vector<uint32_t> gids, solid, one_way;
        std::unique_ptr<MapHandle> handle;
        const bool sizes = positive_int(width, "width", w, f) && positive_int(height, "height", h, f) &&
                           positive_int(tile_w, "tile-width", tw, f) && positive_int(tile_h, "tile-height", th, f);
        if (sizes)
            guarded(f, "make-tilemap", [&] {  // the gid lists are C++ vectors
                // Refused before a cell is converted, as a loaded map's size is.
                if (const std::string p = map_size_problem(w, h, tw, th, kMaxMapCells); !p.empty()) {
                    fail_text(f, "out-of-range", nullptr, p.c_str());
                    return;
                }
                bool ok = true;
                if (scm_is_vector(cells)) {
                    const size_t n = scm_c_vector_length(cells);
                    for (size_t i = 0; ok && i < n; ++i) {
                        SCM g = scm_c_vector_ref(cells, i);
                        ok = scm_is_unsigned_integer(g, 0, 0xFFFFFFFFu);
                        if (ok) gids.push_back(scm_to_uint32(g));
                        else fail(f, "wrong-type-arg", scm_list_2(scm_from_size_t(i), g), "cells: element ~S is not a gid: ~S");
                    }
                } else {
                    ok = gid_list(cells, gids, "cells", f);
                }
                if (!ok || !gid_list(solid_gids, solid, "solid-gids", f)) return;
                if (!SCM_UNBNDP(one_way_gids) && !gid_list(one_way_gids, one_way, "one-way-gids", f)) return;
                handle = std::make_unique<MapHandle>();
                handle->map = ds::make_tilemap(w, h, tw, th, std::move(gids), std::move(solid), kMaxMapCells,
                                               std::move(one_way));
                handle->grid = handle->map.solid_grid();
            });
        if (handle) result = wrap(std::move(handle));
    }
    if (f) raise(f);
    return result;
}

SCM tilemap_p(SCM obj) { return scm_from_bool(is_tilemap(obj)); }

SCM tilemap_width(SCM m) { return map_accessor(m, "tilemap-width", [](const Tilemap& t) { return scm_from_int(t.width); }); }
SCM tilemap_height(SCM m) { return map_accessor(m, "tilemap-height", [](const Tilemap& t) { return scm_from_int(t.height); }); }
SCM tilemap_tile_width(SCM m) { return map_accessor(m, "tilemap-tile-width", [](const Tilemap& t) { return scm_from_int(t.tile_width); }); }
SCM tilemap_tile_height(SCM m) { return map_accessor(m, "tilemap-tile-height", [](const Tilemap& t) { return scm_from_int(t.tile_height); }); }

// Cell indexes are exact integers (any, since cells outside the map are empty).
void check_cell(SCM col, SCM row, Failure& f) {
    const struct {
        SCM v;
        const char* name;
    } cell[] = {{col, "col"}, {row, "row"}};
    for (const auto& [v, name] : cell)
        if (!scm_is_signed_integer(v, INT64_MIN, INT64_MAX)) {
            fail_arg(f, name, v, "an exact integer cell index");
            raise(f);
        }
}

SCM tilemap_cell_solid_p(SCM m, SCM col, SCM row) {
    Failure f;
    if (!check_map(m, "tilemap-cell-solid?", f)) raise(f);
    check_cell(col, row, f);
    return scm_from_bool(tilemap_handle(m).grid.solid(scm_to_int64(col), scm_to_int64(row)));
}

SCM tilemap_cell_one_way_p(SCM m, SCM col, SCM row) {
    Failure f;
    if (!check_map(m, "tilemap-cell-one-way?", f)) raise(f);
    check_cell(col, row, f);
    return scm_from_bool(tilemap_handle(m).grid.one_way(scm_to_int64(col), scm_to_int64(row)));
}

// A new map with one cell changed; the old map is untouched (scenes are
// values: rewinding to a scene that held it still finds the old tile). The
// copy shares the old map's cells but for the edited chunk of the layer and
// of the grid, and its grid has a revision of its own, so no settled body
// sleeps through the edit.
SCM tilemap_set_tile(SCM m, SCM col, SCM row, SCM gid, SCM layer) {
    Failure f{"tilemap-set-tile"};
    if (!is_tilemap(m)) {
        fail_arg(f, "tm", m, "a tilemap");
        raise(f);
    }
    check_cell(col, row, f);
    const MapHandle& old = tilemap_handle(m);
    uint32_t g = 0;
    if (!from_scm(gid, g, Arg("gid"), f)) raise(f);
    const size_t layers = old.map.layers.size();
    size_t l = 0;
    if (!SCM_UNBNDP(layer) && !scm_is_unsigned_integer(layer, 0, SIZE_MAX))
        fail_arg(f, "layer", layer, "a tile layer number (an exact integer from 0)");
    else if (!SCM_UNBNDP(layer) && !(layers > 0 && scm_is_unsigned_integer(layer, 0, layers - 1)))
        fail(f, "out-of-range", scm_list_1(layer), "no tile layer ~S");
    else if (!SCM_UNBNDP(layer)) l = scm_to_size_t(layer);
    if (!f && !old.map.gid_known(g)) fail(f, "out-of-range", scm_list_1(gid), "gid ~S belongs to none of the map's tilesets");
    if (f) raise(f);
    const int64_t c = scm_to_int64(col), r = scm_to_int64(row);
    const TileLayer& target = old.map.layers[l];
    if (c < target.origin_col || r < target.origin_row || c - target.origin_col >= target.width ||
        r - target.origin_row >= target.height) {
        fail(f, "out-of-range", scm_list_3(col, row, scm_from_size_t(l)), "cell (~S, ~S) is outside tile layer ~S");
        raise(f);
    }
    SCM result = SCM_BOOL_F;
    {
        std::unique_ptr<MapHandle> handle;
        guarded(f, "tilemap-set-tile", [&] {
            handle = std::make_unique<MapHandle>(old);  // shares all but the edited chunks
            set_tile(handle->map, handle->grid, l, c, r, g);
        });
        if (handle) result = wrap(std::move(handle));
    }
    if (f) raise(f);
    return result;
}

SCM tilemap_solid_extent(SCM m) {
    Failure f;
    if (!check_map(m, "tilemap-solid-extent", f)) raise(f);
    const TileGrid& g = tilemap_handle(m).grid;
    return scm_list_4(scm_from_int64(g.origin_col()), scm_from_int64(g.origin_row()),
                      scm_from_int(g.cols()), scm_from_int(g.rows()));
}

SCM tilemap_gid(SCM m, SCM layer, SCM col, SCM row) {
    Failure f;
    if (!check_map(m, "tilemap-gid", f)) raise(f);
    const Tilemap& t = tilemap_handle(m).map;
    if (!scm_is_unsigned_integer(layer, 0, t.layers.empty() ? 0 : t.layers.size() - 1) || t.layers.empty()) {
        fail(f, "out-of-range", scm_list_1(layer), "no tile layer ~S");
        raise(f);
    }
    check_cell(col, row, f);
    return scm_from_uint32(t.layers[scm_to_size_t(layer)].raw_gid(scm_to_int64(col), scm_to_int64(row)));
}

}  // namespace

void init_tilemap_type() {
    if (scm_is_true(tilemap_type)) return;
    tilemap_type = scm_gc_protect_object(scm_make_foreign_object_type(
        scm_from_utf8_symbol("tilemap"), scm_list_1(scm_from_utf8_symbol("handle")), finalize_tilemap));
}

bool is_tilemap(SCM obj) {
    return SCM_STRUCTP(obj) && scm_is_eq(SCM_STRUCT_VTABLE(obj), tilemap_type) &&
           scm_foreign_object_ref(obj, 0) != nullptr;
}

bool check_map(SCM obj, const char* proc, Failure& f) {
    f.proc = proc;
    if (is_tilemap(obj)) return true;
    fail(f, "wrong-type-arg", scm_list_1(obj), "expected a tilemap, got ~S");
    return false;
}

const MapHandle& tilemap_handle(SCM obj) {
    return *static_cast<const MapHandle*>(scm_foreign_object_ref(obj, 0));
}

bool grid_from_scm(SCM obj, const TileGrid*& grid, Failure& f) {
    grid = nullptr;
    if (scm_is_false(obj)) return true;
    if (is_tilemap(obj)) {
        grid = &tilemap_handle(obj).grid;
        return true;
    }
    fail(f, "wrong-type-arg", scm_list_1(obj), "expected a tilemap or #f, got ~S");
    return false;
}

void register_tilemap_procedures() {
    init_tilemap_type();
    register_tilemap_info_procedures();
    register_tilemap_shape_procedures();
    define_procedure<6, 0, 0, load_tilemap>("%load-tilemap",
        WrapperDoc{"(path solid-gids max-cells max-bytes strict? project)", "load-tilemap", "(downstroke tilemap)"});
    // Exported as they are (re-exported by (downstroke tilemap)): documented here.
    define_procedure<6, 1, 0, make_tilemap>("make-tilemap",
        "(make-tilemap width height tile-width tile-height cells solid-gids [one-way-gids]): a map "
        "made in memory; cells is a vector (or list) of gids, row-major; one-way-gids are one-way "
        "platforms (solid from above only).");
    define_procedure<1, 0, 0, tilemap_p>("tilemap?", "(tilemap? obj): whether obj is a tilemap.");
    define_procedure<1, 0, 0, tilemap_width>("tilemap-width", "(tilemap-width tm): the map's width in cells.");
    define_procedure<1, 0, 0, tilemap_height>("tilemap-height", "(tilemap-height tm): the map's height in cells.");
    define_procedure<1, 0, 0, tilemap_tile_width>("tilemap-tile-width", "(tilemap-tile-width tm): the width of one tile in px.");
    define_procedure<1, 0, 0, tilemap_tile_height>("tilemap-tile-height", "(tilemap-tile-height tm): the height of one tile in px.");
    define_procedure<3, 0, 0, tilemap_cell_solid_p>("tilemap-cell-solid?",
        "(tilemap-cell-solid? tm col row): whether that cell blocks bodies.");
    define_procedure<4, 1, 0, tilemap_set_tile>("tilemap-set-tile",
        "(tilemap-set-tile tm col row gid [layer]): a new map whose cell (col, row) of tile layer "
        "number layer (0) holds gid (0 clears it), solidity and all; tm is unchanged.");
    define_procedure<3, 0, 0, tilemap_cell_one_way_p>("tilemap-cell-one-way?",
        "(tilemap-cell-one-way? tm col row): whether that cell is a one-way platform, which stops "
        "bodies only from above.");
    define_procedure<1, 0, 0, tilemap_solid_extent>("tilemap-solid-extent",
        "(tilemap-solid-extent tm): the block of cells that can be solid, as the list "
        "(first-col first-row cols rows); every cell outside it is empty (infinite maps may start "
        "at negative cells).");
    define_procedure<4, 0, 0, tilemap_gid>("tilemap-gid",
        "(tilemap-gid tm layer col row): the raw gid (flip bits kept) of a cell of tile layer "
        "number layer, 0 when empty.");
}

}  // namespace ds::guile
