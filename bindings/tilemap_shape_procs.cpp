// SPDX-License-Identifier: MIT
// The shape queries the pure-Scheme reference reads cells through
// (semantics §12): a cell's solid part, and the grid's steepest ramp.
#include <cstdint>

#include "convert.hpp"
#include "failure.hpp"
#include "registry.hpp"
#include "tilemap_type.hpp"

namespace ds::guile {

namespace {

SCM cut_symbol(Cut cut) {
    static SCM box = scm_permanent_object(scm_from_utf8_symbol("box"));
    static SCM floor = scm_permanent_object(scm_from_utf8_symbol("floor"));
    static SCM ceiling = scm_permanent_object(scm_from_utf8_symbol("ceiling"));
    return cut == Cut::Floor ? floor : cut == Cut::Ceiling ? ceiling : box;
}

// Slants as a list of lists (ax ay bx by), in order.
SCM slant_list(const Slant* ls, int n) {
    SCM out = SCM_EOL;
    for (int i = n - 1; i >= 0; --i)
        out = scm_cons(scm_list_4(scm_from_int32(ls[i].ax), scm_from_int32(ls[i].ay), scm_from_int32(ls[i].bx),
                                  scm_from_int32(ls[i].by)),
                       out);
    return out;
}

// A box or a ramp is the 10 slots it has always been; a polygon cut by
// several slants adds an 11th, the further slants as lists (ax ay bx by),
// and one slanted on its underside too a 12th, the underside's slants.
SCM shape_vector(const CellShape& s) {
    SCM v = scm_c_make_vector(s.two_sided() ? 12 : s.n_more > 0 ? 11 : 10, SCM_BOOL_F);
    const int32_t nums[] = {s.x0, s.y0, s.x1, s.y1};
    for (size_t i = 0; i < 4; ++i) scm_c_vector_set_x(v, i, scm_from_int32(nums[i]));
    scm_c_vector_set_x(v, 4, cut_symbol(s.cut));
    const int32_t line[] = {s.ax, s.ay, s.bx, s.by};
    for (size_t i = 0; i < 4; ++i) scm_c_vector_set_x(v, 5 + i, scm_from_int32(line[i]));
    scm_c_vector_set_x(v, 9, scm_from_bool(s.one_way));
    if (s.n_more > 0 || s.two_sided()) scm_c_vector_set_x(v, 10, slant_list(s.more.data(), s.n_more));
    if (s.two_sided()) scm_c_vector_set_x(v, 11, slant_list(s.under.data(), s.n_under));
    return v;
}

SCM tilemap_cell_shape(SCM m, SCM col, SCM row) {
    Failure f;
    if (!check_map(m, "tilemap-cell-shape", f)) raise(f);
    if (!scm_is_signed_integer(col, INT64_MIN, INT64_MAX)) fail_arg(f, "col", col, "an exact integer cell index");
    else if (!scm_is_signed_integer(row, INT64_MIN, INT64_MAX)) fail_arg(f, "row", row, "an exact integer cell index");
    if (f) raise(f);
    const TileGrid& g = tilemap_handle(m).grid;
    const int64_t c = scm_to_int64(col), r = scm_to_int64(row);
    switch (g.cell(c, r)) {
        case kSolidCell: return scm_from_utf8_symbol("solid");
        case kOneWayCell: return scm_from_utf8_symbol("one-way");
        case kShapedCell: return shape_vector(*g.shape(c, r));
        default: return SCM_BOOL_F;
    }
}

SCM tilemap_steepest_ramp(SCM m) {
    Failure f;
    if (!check_map(m, "tilemap-steepest-ramp", f)) raise(f);
    return scm_from_double(tilemap_handle(m).grid.steepest_ramp());
}

}  // namespace

void register_tilemap_shape_procedures() {
    define_procedure<3, 0, 0, tilemap_cell_shape>("tilemap-cell-shape",
        "(tilemap-cell-shape tm col row): the cell's solid part: #f for none, "
        "'solid or 'one-way for the whole cell, or a shape #(x0 y0 x1 y1 cut ax ay bx by one-way?) "
        "in tile px: the box [x0, x1) x [y0, y1), cut 'box, or 'floor (what lies below the line "
        "through (ax, ay) and (bx, by)) or 'ceiling (what lies above it). A convex polygon cut by "
        "several slants on one side has an 11th slot, its further slants left to right, each (ax ay bx by): "
        "it keeps what lies on the kept side of every one. One slanted on its underside too is a 'floor "
        "shape with a 12th slot, its underside's slants left to right: it keeps also what lies above "
        "every one of those.");
    define_procedure<1, 0, 0, tilemap_steepest_ramp>("tilemap-steepest-ramp",
        "(tilemap-steepest-ramp tm): the greatest |dy/dx| among the ramps the map's cells have had, "
        "as a flonum (0.0 for none): a walking body snaps down a ramp by at most |vx| times it.");
}

}  // namespace ds::guile
