// SPDX-License-Identifier: MIT
// The spatial queries of (downstroke query) and the tile queries, as native
// procedures: decode the entities' boxes, ask the core (query.hpp), hand back
// the very entity objects that matched, in list order.
#include "detail/placed_shape.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "convert.hpp"
#include "keys.hpp"
#include "list_walk.hpp"
#include "plist.hpp"
#include "query.hpp"
#include "registry.hpp"
#include "tilemap_type.hpp"

namespace ds::guile {

namespace {

// Kept per thread between calls, so a warm query does not allocate. Only
// plain data: the entities themselves stay in the caller's lists.
struct QueryScratch {
    std::vector<Box> a, b;
    std::vector<uint32_t> found, found_b;  // positions in the caller's list
    std::vector<int32_t> a_in_b, b_in_a;
    std::vector<std::pair<uintptr_t, int32_t>> index;  // addresses of one list, sorted
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    PairQueryScratch pair_scratch;
    std::vector<RayHit> hits;
};
QueryScratch& scratch() {
    thread_local QueryScratch s;
    return s;
}

// The hit plists' keywords, interned once Guile runs.
struct HitKeys {
    SCM x, y, distance, normal_x, normal_y, entity, col, row;
};
HitKeys hit_keys;

bool proper_list(SCM list, const char* what, Failure& f) {
    if (scm_ilength(list) >= 0) return true;  // Floyd's check: circular and dotted lists fail
    if (circular<1>(list)) fail_circular(f, what, "a list of entities", list);
    else fail_arg(f, Arg(what), list, "a proper list of entities");
    return false;
}

// The boxes of a list of entities, in order.
bool decode_boxes(SCM entities, const char* what, std::vector<Box>& out, Failure& f) {
    out.clear();
    if (!proper_list(entities, what, f)) return false;
    for (SCM l = entities; scm_is_pair(l); l = SCM_CDR(l)) {
        Decoded d;
        if (!decode_entity(SCM_CAR(l), d, f)) return false;
        out.push_back({d.body.x.v, d.body.y.v, d.body.w.v, d.body.h.v});
    }
    return true;
}

// The entities at the ascending positions `at`, as a new list in that order.
SCM pick(SCM entities, const std::vector<uint32_t>& at) {
    SCM head = SCM_EOL, *tail = &head;
    uint32_t k = 0;
    size_t next = 0;
    for (SCM l = entities; scm_is_pair(l) && next < at.size(); l = SCM_CDR(l), ++k)
        if (at[next] == k) {
            *tail = scm_cons(SCM_CAR(l), SCM_EOL);
            tail = SCM_CDRLOC(*tail);
            ++next;
        }
    return head;
}

bool finite_args(std::initializer_list<std::pair<SCM, const char*>> args, double* out, Failure& f) {
    size_t k = 0;
    for (const auto& [v, name] : args)
        if (!from_scm(v, out[k++], Arg(name), f)) return false;
    return true;
}

SCM query_rect(SCM entities, SCM x, SCM y, SCM w, SCM h) {
    Failure f{"scene-query-rect"};
    double v[4];
    QueryScratch& s = scratch();
    if (finite_args({{x, "x"}, {y, "y"}, {w, "width"}, {h, "height"}}, v, f) &&
        decode_boxes(entities, "entities", s.a, f)) {
        s.found.clear();
        guarded(f, nullptr, [&] { ds::query_rect(s.a, {v[0], v[1], v[2], v[3]}, s.found); });
    }
    if (f) raise(f);
    return pick(entities, s.found);
}

SCM query_point(SCM entities, SCM x, SCM y) {
    Failure f{"scene-query-point"};
    double v[2];
    QueryScratch& s = scratch();
    if (finite_args({{x, "x"}, {y, "y"}}, v, f) && decode_boxes(entities, "entities", s.a, f)) {
        s.found.clear();
        guarded(f, nullptr, [&] { ds::query_point(s.a, v[0], v[1], s.found); });
    }
    if (f) raise(f);
    return pick(entities, s.found);
}

// Whether a validated plist's first value under `key` (as entity-ref reads
// it) is equal? to `value`; an absent key matches nothing.
bool chosen(SCM plist, SCM key, SCM value) {
    const SCM v = plist_get(plist, key, SCM_UNDEFINED);
    return !SCM_UNBNDP(v) && scm_is_true(scm_equal_p(v, value));
}

// The entities whose value under `key` is equal? to `value`.
SCM select(SCM entities, SCM key, SCM value) {
    Failure f{"scene-select"};
    if (!scm_is_keyword(key)) fail_arg(f, Arg("key"), key, "a keyword");
    else if (proper_list(entities, "entities", f)) {
        std::vector<uint32_t>& found = scratch().found;
        found.clear();
        uint32_t k = 0;
        for (SCM l = entities; scm_is_pair(l) && !f; l = SCM_CDR(l), ++k) {
            SCM e = SCM_CAR(l);
            if (scm_ilength(e) < 0 || scm_ilength(e) % 2 != 0) {
                fail_arg(f, Arg("entity"), e, "an entity plist");
                break;
            }
            if (chosen(e, key, value)) found.push_back(k);
        }
        if (!f) return pick(entities, found);
    }
    raise(f);
}

// ---- the category filter (semantics §13): the query as a body of category
// `category` that collides with the categories `collides-with` names; an
// entity is kept when the two would meet, as far as each is given.

bool symbol_list(SCM list) {
    if (scm_ilength(list) < 0) return false;  // circular or dotted
    for (; scm_is_pair(list); list = SCM_CDR(list))
        if (!scm_is_symbol(SCM_CAR(list))) return false;
    return true;
}

bool member_q(SCM x, SCM list) { return scm_is_true(scm_memq(x, list)); }

// Whether an entity with these (decoded, checked) keys passes the filter.
bool passes(const Decoded& d, SCM category, SCM collides_with) {
    const SCM own = SCM_UNBNDP(d.category) ? keys->default_category : d.category;
    if (scm_is_true(category) && !SCM_UNBNDP(d.collides_with) && !member_q(category, d.collides_with)) return false;
    return scm_is_false(collides_with) || member_q(own, collides_with);
}

SCM category_filter(SCM who, SCM entities, SCM category, SCM collides_with) {
    // The query the filter serves names the errors.
    static constexpr const char* kQueries[] = {"scene-query-rect", "scene-query-point", "scene-pairs",
                                               "scene-raycast"};
    Failure f{"scene-query"};
    for (const char* q : kQueries)
        if (scm_is_eq(who, scm_from_utf8_symbol(q))) f.proc = q;
    SCM result = entities;
    if (scm_is_true(category) && !scm_is_symbol(category)) {
        fail_arg(f, Arg("category"), category, "a category symbol or #f");
    } else if (scm_is_true(collides_with) && !symbol_list(collides_with)) {
        fail_arg(f, Arg("collides-with"), collides_with, "a list of category symbols or #f");
    } else if (proper_list(entities, "entities", f) && (scm_is_true(category) || scm_is_true(collides_with))) {
        std::vector<uint32_t>& found = scratch().found;
        found.clear();
        uint32_t k = 0;
        for (SCM l = entities; scm_is_pair(l); l = SCM_CDR(l), ++k) {
            Decoded d;
            if (!decode_entity(SCM_CAR(l), d, f)) break;
            if (passes(d, category, collides_with)) found.push_back(k);
        }
        if (!f && found.size() != k) result = pick(entities, found);
    }
    if (f) raise(f);
    return result;
}

// position in `within` of each element of `of` (eq?), or -1; all -1 when the
// lists share nothing, which is the common case (bullets × enemies). The
// addresses are only compared: both lists keep their objects alive for the
// call, and Guile's collector does not move objects.
void shared_positions(SCM of, SCM within, std::vector<std::pair<uintptr_t, int32_t>>& index,
                      std::vector<int32_t>& out) {
    index.clear();
    int32_t k = 0;
    for (SCM l = within; scm_is_pair(l); l = SCM_CDR(l), ++k) index.emplace_back(SCM_UNPACK(SCM_CAR(l)), k);
    std::sort(index.begin(), index.end());
    out.clear();
    for (SCM l = of; scm_is_pair(l); l = SCM_CDR(l)) {
        const uintptr_t a = SCM_UNPACK(SCM_CAR(l));
        const auto it = std::lower_bound(index.begin(), index.end(), std::pair<uintptr_t, int32_t>{a, -1});
        out.push_back(it != index.end() && it->first == a ? it->second : -1);
    }
}

SCM pairs(SCM as, SCM bs) {
    Failure f{"scene-pairs"};
    QueryScratch& s = scratch();
    if (decode_boxes(as, "first group", s.a, f) && decode_boxes(bs, "second group", s.b, f)) {
        shared_positions(as, bs, s.index, s.a_in_b);
        shared_positions(bs, as, s.index, s.b_in_a);
        s.pairs.clear();
        guarded(f, nullptr, [&] { overlapping_pairs(s.a, s.b, {s.a_in_b, s.b_in_a}, s.pair_scratch, s.pairs); });
    }
    if (f) raise(f);
    SCM va = scm_vector(as), vb = scm_vector(bs), head = SCM_EOL, *tail = &head;
    for (const auto& [i, j] : s.pairs) {
        *tail = scm_cons(scm_cons(SCM_SIMPLE_VECTOR_REF(va, i), SCM_SIMPLE_VECTOR_REF(vb, j)), SCM_EOL);
        tail = SCM_CDRLOC(*tail);
    }
    return head;
}

// scene-pairs with both groups chosen by (key . value): one walk of the list
// decodes each entity once and files it under either group, or both.
SCM pairs_by_key(SCM entities, SCM key_a, SCM value_a, SCM key_b, SCM value_b) {
    Failure f{"scene-pairs"};
    QueryScratch& s = scratch();
    if (!scm_is_keyword(key_a)) fail_arg(f, Arg("where-a key"), key_a, "a keyword");
    else if (!scm_is_keyword(key_b)) fail_arg(f, Arg("where-b key"), key_b, "a keyword");
    else if (proper_list(entities, "entities", f)) {
        s.a.clear(), s.b.clear(), s.a_in_b.clear(), s.b_in_a.clear(), s.found.clear(), s.found_b.clear();
        uint32_t k = 0;
        for (SCM l = entities; scm_is_pair(l); l = SCM_CDR(l), ++k) {
            Decoded d;
            if (!decode_entity(SCM_CAR(l), d, f)) break;
            const bool in_a = chosen(SCM_CAR(l), key_a, value_a), in_b = chosen(SCM_CAR(l), key_b, value_b);
            const Box box{d.body.x.v, d.body.y.v, d.body.w.v, d.body.h.v};
            if (in_a) s.a.push_back(box), s.found.push_back(k), s.a_in_b.push_back(in_b ? static_cast<int32_t>(s.b.size()) : -1);
            if (in_b) s.b.push_back(box), s.found_b.push_back(k), s.b_in_a.push_back(in_a ? static_cast<int32_t>(s.a.size() - 1) : -1);
        }
        if (!f) {
            s.pairs.clear();
            guarded(f, nullptr, [&] { overlapping_pairs(s.a, s.b, {s.a_in_b, s.b_in_a}, s.pair_scratch, s.pairs); });
        }
    }
    if (f) raise(f);
    SCM all = scm_vector(entities), head = SCM_EOL, *tail = &head;
    for (const auto& [i, j] : s.pairs) {
        *tail = scm_cons(scm_cons(SCM_SIMPLE_VECTOR_REF(all, s.found[i]), SCM_SIMPLE_VECTOR_REF(all, s.found_b[j])),
                         SCM_EOL);
        tail = SCM_CDRLOC(*tail);
    }
    return head;
}

SCM hit_plist(const RayHit& h, double length, SCM entities_vector) {
    SCM tail = h.body >= 0
                   ? scm_list_2(hit_keys.entity, SCM_SIMPLE_VECTOR_REF(entities_vector, h.body))
                   : scm_list_4(hit_keys.col, scm_from_int64(h.col), hit_keys.row, scm_from_int64(h.row));
    return scm_cons_star(hit_keys.x, scm_list_n(scm_from_double(h.x), hit_keys.y, scm_from_double(h.y),
                                                 hit_keys.distance, scm_from_double(h.t * length),
                                                 hit_keys.normal_x, scm_from_int(h.nx), hit_keys.normal_y,
                                                 scm_from_int(h.ny), tail, SCM_UNDEFINED));
}

SCM raycast(SCM entities, SCM tilemap, SCM x0, SCM y0, SCM x1, SCM y1, SCM all) {
    Failure f{"scene-raycast"};
    double v[4];
    const TileGrid* grid = nullptr;
    QueryScratch& s = scratch();
    if (finite_args({{x0, "x0"}, {y0, "y0"}, {x1, "x1"}, {y1, "y1"}}, v, f) && grid_from_scm(tilemap, grid, f) &&
        decode_boxes(entities, "entities", s.a, f)) {
        if (v[0] == v[2] && v[1] == v[3]) {
            fail(f, "out-of-range", scm_list_2(x0, y0), "a ray of zero length, from (~S, ~S) to itself");
        } else {
            const bool every = scm_is_true(all);
            s.hits.clear();
            guarded(f, nullptr, [&] {
                const Segment seg{v[0], v[1], v[2], v[3]};
                raycast_boxes(s.a, seg, s.hits);
                if (grid) raycast_cells(*grid, seg, !every, s.hits);
                sort_hits(s.hits);
                if (!every && s.hits.size() > 1) s.hits.resize(1);
            });
        }
    }
    if (f) raise(f);
    const double length = std::hypot(v[2] - v[0], v[3] - v[1]);
    SCM vec = scm_vector(entities), out = SCM_EOL;
    for (size_t k = s.hits.size(); k-- > 0;) out = scm_cons(hit_plist(s.hits[k], length, vec), out);
    if (!scm_is_true(all)) return scm_is_pair(out) ? SCM_CAR(out) : SCM_BOOL_F;
    return out;
}

// ---- tile queries

bool map_arg(SCM map, const MapHandle*& out, Failure& f) {
    if (is_tilemap(map)) return out = &tilemap_handle(map), true;
    fail_arg(f, Arg("tilemap"), map, "a tilemap");
    return false;
}

// The cell of a world coordinate, clamped as physics clamps (tile_grid.hpp).
int64_t cell_at(double v, int tile) { return cell_of(Num::flonum(v), tile); }

SCM tilemap_solid_cells(SCM map, SCM x, SCM y, SCM w, SCM h) {
    Failure f{"tilemap-solid-cells"};
    const MapHandle* m = nullptr;
    double v[4];
    if (map_arg(map, m, f) && finite_args({{x, "x"}, {y, "y"}, {w, "width"}, {h, "height"}}, v, f)) {
        const TileGrid& g = m->grid;
        // The cells a box [x, x+w) × [y, y+h) covers (none when a size is
        // not positive), clipped to the grid.
        const CellRange cols = g.clip_cols(cells_of(Num::flonum(v[0]), Num::flonum(v[2]), g.tile_width()));
        const CellRange rows = g.clip_rows(cells_of(Num::flonum(v[1]), Num::flonum(v[3]), g.tile_height()));
        SCM head = SCM_EOL, *tail = &head;
        const shape_math::Span span{v[0], v[0] + v[2]};
        auto part_in = [&](int64_t c, int64_t r) {  // a solid shape the box overlaps (semantics §12)
            const CellShape* s = g.shape(c, r);
            return s && !s->one_way && shape_math::Placed(*s, c, r, g).overlaps(span, v[1], v[1] + v[3]);
        };
        for (int64_t r = rows.first; r <= rows.last; ++r)
            for (int64_t c = cols.first; c <= cols.last; ++c)
                if (g.solid(c, r) || part_in(c, r)) {
                    *tail = scm_cons(scm_cons(scm_from_int64(c), scm_from_int64(r)), SCM_EOL);
                    tail = SCM_CDRLOC(*tail);
                }
        return head;
    }
    raise(f);
}

SCM tilemap_solid_at(SCM map, SCM x, SCM y) {
    Failure f{"tilemap-solid-at?"};
    const MapHandle* m = nullptr;
    double v[2];
    if (!map_arg(map, m, f) || !finite_args({{x, "x"}, {y, "y"}}, v, f)) raise(f);
    return scm_from_bool(m->grid.solid_at(v[0], v[1]));
}

// The gid (flip bits removed) at a world point: of the layer given by number
// or name, or of the topmost visible layer with a tile there; 0 for none.
SCM tilemap_gid_at(SCM map, SCM x, SCM y, SCM layer) {
    Failure f{"tilemap-gid-at"};
    const MapHandle* m = nullptr;
    double v[2];
    if (!map_arg(map, m, f) || !finite_args({{x, "x"}, {y, "y"}}, v, f)) raise(f);
    const Tilemap& t = m->map;
    const int64_t c = cell_at(v[0], t.tile_width), r = cell_at(v[1], t.tile_height);
    if (!SCM_UNBNDP(layer) && scm_is_true(layer)) {
        if (scm_is_unsigned_integer(layer, 0, t.layers.empty() ? 0 : t.layers.size() - 1) && !t.layers.empty())
            return scm_from_uint32(t.layers[scm_to_size_t(layer)].raw_gid(c, r) & kGidMask);
        if (!scm_is_string(layer)) {
            fail_arg(f, Arg("layer"), layer, "a tile layer's number or name, or #f");
            raise(f);
        }
        for (const TileLayer& l : t.layers) {
            SCM name = scm_from_utf8_stringn(l.name.data(), l.name.size());
            if (scm_is_true(scm_string_equal_p(name, layer))) return scm_from_uint32(l.raw_gid(c, r) & kGidMask);
        }
        fail(f, "out-of-range", scm_list_1(layer), "no tile layer named ~S");
        raise(f);
    }
    for (size_t k = t.layers.size(); k-- > 0;)
        if (t.layers[k].visible)
            if (const uint32_t gid = t.layers[k].raw_gid(c, r) & kGidMask) return scm_from_uint32(gid);
    return scm_from_int(0);
}

SCM keyword(const char* name) { return scm_gc_protect_object(scm_from_utf8_keyword(name)); }

}  // namespace

void register_query_procedures() {
    hit_keys = {keyword("x"),        keyword("y"),      keyword("distance"), keyword("normal-x"),
                keyword("normal-y"), keyword("entity"), keyword("col"),      keyword("row")};
    constexpr const char* query = "(downstroke query)";
    define_procedure<5, 0, 0, query_rect>("%query-rect", WrapperDoc{"(entities x y w h)", "scene-query-rect", query});
    define_procedure<3, 0, 0, query_point>("%query-point", WrapperDoc{"(entities x y)", "scene-query-point", query});
    define_procedure<3, 0, 0, select>("%select", WrapperDoc{"(entities key value)", "scene-select", query});
    define_procedure<4, 0, 0, category_filter>("%category-filter",
        WrapperDoc{"(who entities category collides-with)", "scene-query-rect", query});
    define_procedure<2, 0, 0, pairs>("%pairs", WrapperDoc{"(as bs)", "scene-pairs", query});
    define_procedure<5, 0, 0, pairs_by_key>("%pairs-by-key",
        WrapperDoc{"(entities key-a value-a key-b value-b)", "scene-pairs", query});
    define_procedure<7, 0, 0, raycast>("%raycast",
        WrapperDoc{"(entities tilemap x0 y0 x1 y1 all?)", "scene-raycast", query});
    define_procedure<5, 0, 0, tilemap_solid_cells>("tilemap-solid-cells",
        "(tilemap-solid-cells map x y w h): the solid cells, as (col . row) in row-major order, "
        "that the box [x, x+w) × [y, y+h) covers; a cell solid in part (a ramp, a part-tile box) when "
        "the box overlaps its solid shape.");
    define_procedure<3, 0, 0, tilemap_solid_at>("tilemap-solid-at?",
        "(tilemap-solid-at? map x y): whether the world point (x, y) is in a solid part of the map: a "
        "solid cell, or inside the solid shape of a cell that is solid in part (a ramp, a part-tile box).");
    define_procedure<3, 1, 0, tilemap_gid_at>("tilemap-gid-at",
        "(tilemap-gid-at map x y [layer]): the gid (flip bits removed) at the world point (x, y) in the "
        "tile layer layer (its number, as tilemap-gid takes, or its name), or in the topmost visible "
        "layer with a tile there; 0 for none.");
}

}  // namespace ds::guile
