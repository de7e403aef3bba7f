// SPDX-License-Identifier: MIT
#include "tilemap_type.hpp"

#include <cmath>
#include <memory>
#include <string>

#include "convert.hpp"
#include "failure.hpp"
#include "list_walk.hpp"
#include "registry.hpp"
#include "tilemap_info.hpp"
#include "tilemap/tile_shapes.hpp"

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

// `max`: kGidMask for lists of tiles (solid-gids), 0xFFFFFFFF for cells,
// which may carry flip bits.
bool gid_list(SCM list, std::vector<uint32_t>& out, const char* what, Failure& f, uint32_t max = kGidMask) {
    SCM p = list;
    Tortoise tortoise;
    for (; scm_is_pair(p); p = SCM_CDR(p)) {
        if (tortoise.caught(p)) {
            fail_circular(f, what, "a list of gids", list);
            return false;
        }
        SCM g = SCM_CAR(p);
        if (!scm_is_unsigned_integer(g, 0, max)) {
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

// A finite real number.
bool finite_real(SCM v, double& out) {
    if (!scm_is_real(v)) return false;
    out = scm_to_double(v);
    return std::isfinite(out);
}

// One shape of make-tilemap's `shapes`: (rect x y w h) or (polygon (x . y) …),
// in tile px.
bool shape_spec(SCM spec, MapObject& o) {
    static SCM rect = scm_permanent_object(scm_from_utf8_symbol("rect"));
    static SCM polygon = scm_permanent_object(scm_from_utf8_symbol("polygon"));
    if (!scm_is_pair(spec) || scm_ilength(spec) < 1) return false;
    SCM rest = SCM_CDR(spec);
    if (scm_is_eq(SCM_CAR(spec), rect)) {
        double v[4];
        for (double& d : v) {
            if (!scm_is_pair(rest) || !finite_real(SCM_CAR(rest), d)) return false;
            rest = SCM_CDR(rest);
        }
        o.shape = ObjectShape::Rectangle;
        o.x = v[0], o.y = v[1], o.width = v[2], o.height = v[3];
        return scm_is_null(rest);
    }
    if (!scm_is_eq(SCM_CAR(spec), polygon)) return false;
    o.shape = ObjectShape::Polygon;
    for (; scm_is_pair(rest); rest = SCM_CDR(rest)) {
        SCM p = SCM_CAR(rest);
        ObjectPoint pt;
        if (!scm_is_pair(p) || !finite_real(SCM_CAR(p), pt.x) || !finite_real(SCM_CDR(p), pt.y)) return false;
        o.points.push_back(pt);
    }
    return scm_is_null(rest);
}

// make-tilemap's `shapes`: a proper list of (gid . shape), each a shape a
// tile_w × tile_h tile can have (tile_solid_part finds no problem in it).
bool shape_list(SCM list, int tile_w, int tile_h, std::vector<GidShape>& out, Failure& f) {
    if (scm_ilength(list) < 0) {  // improper or circular
        fail_arg(f, "shapes", list, "a list of (gid . shape)");
        return false;
    }
    for (SCM p = list; scm_is_pair(p); p = SCM_CDR(p)) {
        SCM item = SCM_CAR(p);
        GidShape s;
        if (!scm_is_pair(item) || !scm_is_unsigned_integer(SCM_CAR(item), 1, kGidMask) ||
            scm_ilength(SCM_CDR(item)) < 0 || !shape_spec(SCM_CDR(item), s.object)) {
            fail(f, "wrong-type-arg", scm_list_1(item),
                 "shapes: expected (gid . (rect x y w h)) or (gid . (polygon (x . y) ...)) with finite numbers, got ~S");
            return false;
        }
        s.gid = scm_to_uint32(SCM_CAR(item));
        if (const TileSolidPart p = tile_solid_part({s.object}, tile_w, tile_h, 0); !p.problem.empty()) {
            fail(f, "out-of-range", scm_list_2(SCM_CAR(item), scm_from_utf8_string(p.problem.c_str())),
                 "shapes: the shape of gid ~S: ~A");
            return false;
        }
        out.push_back(std::move(s));
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
    // The range an int holds safely, said in the message (a refusal of
    // 2^31 − 1 as "not positive" would puzzle); map_size_problem then
    // applies the map limits.
    return from_scm(v, out, what, f, 1, 1 << 24);
}

SCM make_tilemap(SCM width, SCM height, SCM tile_w, SCM tile_h, SCM cells, SCM solid_gids, SCM one_way_gids,
                 SCM shapes) {
    Failure f{"make-tilemap"};
    SCM result = SCM_BOOL_F;
    {
        int w = 0, h = 0, tw = 0, th = 0;
        std::vector<uint32_t> gids, solid, one_way;
        std::vector<GidShape> gid_shapes;
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
                    ok = gid_list(cells, gids, "cells", f, 0xFFFFFFFFu);
                }
                if (!ok || !gid_list(solid_gids, solid, "solid-gids", f)) return;
                if (!SCM_UNBNDP(one_way_gids) && !gid_list(one_way_gids, one_way, "one-way-gids", f)) return;
                if (!SCM_UNBNDP(shapes) && !shape_list(shapes, tw, th, gid_shapes, f)) return;
                handle = std::make_unique<MapHandle>();
                handle->map = ds::make_tilemap(w, h, tw, th, std::move(gids), std::move(solid), kMaxMapCells,
                                               std::move(one_way), std::move(gid_shapes));
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

// Per cell, as the grid holds it: a shaped cell is solid (or one-way) in part.
SCM tilemap_cell_solid_p(SCM m, SCM col, SCM row) {
    Failure f;
    if (!check_map(m, "tilemap-cell-solid?", f)) raise(f);
    check_cell(col, row, f);
    const TileGrid& g = tilemap_handle(m).grid;
    const int64_t c = scm_to_int64(col), r = scm_to_int64(row);
    const CellShape* s = g.shape(c, r);
    return scm_from_bool(g.solid(c, r) || (s && !s->one_way));
}

SCM tilemap_cell_one_way_p(SCM m, SCM col, SCM row) {
    Failure f;
    if (!check_map(m, "tilemap-cell-one-way?", f)) raise(f);
    check_cell(col, row, f);
    const TileGrid& g = tilemap_handle(m).grid;
    const int64_t c = scm_to_int64(col), r = scm_to_int64(row);
    const CellShape* s = g.shape(c, r);
    return scm_from_bool(g.one_way(c, r) || (s && s->one_way));
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
    if (g.cols() == 0 || g.rows() == 0) return SCM_BOOL_F;  // no block: (0 0 0 0) would claim one at the origin
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
    define_procedure<6, 2, 0, make_tilemap>("make-tilemap",
        "(make-tilemap width height tile-width tile-height cells solid-gids [one-way-gids shapes]): a "
        "map made in memory; cells is a vector (or list) of gids, row-major, flip bits allowed; "
        "one-way-gids are one-way platforms (solid from above only); shapes gives gids a collision "
        "shape in tile px, as a list of (gid . (rect x y w h)) or (gid . (polygon (x . y) ...)), "
        "read as Tiled's collision editor's (a shaped gid in one-way-gids is a one-way shape; a shape "
        "drawn past the tile is its part inside it; a convex polygon collides as drawn, its slanted "
        "edges on its top, its underside or both, and one that is not convex is refused, as a shape "
        "with no area is).");
    define_procedure<1, 0, 0, tilemap_p>("tilemap?", "(tilemap? obj): whether obj is a tilemap.");
    define_procedure<1, 0, 0, tilemap_width>("tilemap-width", "(tilemap-width tm): the map's width in cells.");
    define_procedure<1, 0, 0, tilemap_height>("tilemap-height", "(tilemap-height tm): the map's height in cells.");
    define_procedure<1, 0, 0, tilemap_tile_width>("tilemap-tile-width", "(tilemap-tile-width tm): the width of one tile in px.");
    define_procedure<1, 0, 0, tilemap_tile_height>("tilemap-tile-height", "(tilemap-tile-height tm): the height of one tile in px.");
    define_procedure<3, 0, 0, tilemap_cell_solid_p>("tilemap-cell-solid?",
        "(tilemap-cell-solid? tm col row): whether that cell blocks bodies, wholly or in part (a "
        "solid shape: tilemap-cell-shape tells which).");
    define_procedure<4, 1, 0, tilemap_set_tile>("tilemap-set-tile",
        "(tilemap-set-tile tm col row gid [layer]): a new map whose cell (col, row) of tile layer "
        "number layer (0) holds gid (0 clears it), solidity and all; tm is unchanged.");
    define_procedure<3, 0, 0, tilemap_cell_one_way_p>("tilemap-cell-one-way?",
        "(tilemap-cell-one-way? tm col row): whether that cell is a one-way platform, which stops "
        "bodies only from above.");
    define_procedure<1, 0, 0, tilemap_solid_extent>("tilemap-solid-extent",
        "(tilemap-solid-extent tm): the block of cells that can be solid, as the list "
        "(first-col first-row cols rows); every cell outside it is empty (infinite maps may start "
        "at negative cells). #f when no cell can be solid: a map with no tile layers, or an infinite "
        "map whose layers hold no chunk.");
    define_procedure<4, 0, 0, tilemap_gid>("tilemap-gid",
        "(tilemap-gid tm layer col row): the raw gid (flip bits kept) of a cell of tile layer "
        "number layer, 0 when empty.");
}

}  // namespace ds::guile
