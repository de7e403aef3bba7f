// SPDX-License-Identifier: MIT
#include "contact_report.hpp"

#include <algorithm>
#include <iterator>

#include "contacts.hpp"
#include "keys.hpp"

namespace ds::guile {

void ContactIndex::gather(std::span<const IndexPair> log, std::span<const uint8_t> sides,
                          std::span<const Body> bodies) {
    clear();
    auto reported = [&](const IndexPair& p) {
        return bodies[p.first].reports_pairs() || bodies[p.second].reports_pairs();
    };
    seen.clear();
    std::copy_if(log.begin(), log.end(), std::back_inserter(seen), reported);
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    // Each pair once, where first resolved: sub-frames may resolve it again.
    used.assign(seen.size(), 0);
    for (size_t at = 0; at < log.size(); ++at) {
        const IndexPair& p = log[at];
        if (!reported(p)) continue;
        const size_t k = static_cast<size_t>(std::lower_bound(seen.begin(), seen.end(), p) - seen.begin());
        if (used[k]) continue;
        used[k] = 1;
        const uint8_t side = at < sides.size() ? sides[at] : 0;
        pairs.push_back(p);
        pair_sides.push_back(side);
        if (bodies[p.first].contacts) touching.push_back({p.first, p.second, side});
        if (bodies[p.second].contacts) touching.push_back({p.second, p.first, opposite_side(side)});
    }
    std::sort(touching.begin(), touching.end());
}

SCM entity_name(SCM entity, size_t index) {
    const SCM id = plist_get(entity, keys->key[kId], SCM_BOOL_F);
    return scm_is_true(id) ? id : scm_from_size_t(index);
}

SCM entity_names(SCM entities, std::span<const int64_t> ids) {
    // Entities in [0, n), their names in [n, 2n) as they are first asked
    // for: a report names a few entities of a long list (the ones touching
    // a sensor), and each name walks its entity's plist.
    const size_t n = scm_to_size_t(scm_length(entities));
    const SCM names = scm_c_make_vector(2 * n, SCM_UNDEFINED);
    size_t i = 0;
    for (SCM p = entities; scm_is_pair(p); p = SCM_CDR(p), ++i) SCM_SIMPLE_VECTOR_SET(names, i, SCM_CAR(p));
    // An even tag is 0 (no id, or #f) or the id's own bits, which its plist
    // keeps alive; an odd one is an interned value's number (plist.hpp).
    for (size_t k = 0; k < ids.size() && k < n; ++k)
        if ((ids[k] & 1) == 0)
            SCM_SIMPLE_VECTOR_SET(names, n + k, ids[k] == 0 ? scm_from_size_t(k) : SCM_PACK(static_cast<scm_t_bits>(ids[k])));
    return names;
}

SCM name_at(SCM names, size_t k) {
    const size_t n = SCM_SIMPLE_VECTOR_LENGTH(names) / 2;
    SCM name = SCM_SIMPLE_VECTOR_REF(names, n + k);
    if (SCM_UNBNDP(name)) {
        name = entity_name(SCM_SIMPLE_VECTOR_REF(names, k), k);
        SCM_SIMPLE_VECTOR_SET(names, n + k, name);
    }
    return name;
}

namespace {

SCM side_symbol(uint8_t side) {
    return side != 0 ? keys->side_symbol[__builtin_ctz(side)] : SCM_BOOL_F;
}

}  // namespace

SCM touching_names(const ContactIndex& index, size_t i, SCM names, bool with_sides) {
    const auto body = static_cast<uint32_t>(i);
    auto at = std::lower_bound(index.touching.begin(), index.touching.end(), Touch{body, 0, 0});
    auto end = at;
    while (end != index.touching.end() && end->body == body) ++end;
    SCM list = SCM_EOL;
    while (end != at) {
        --end;
        const SCM name = name_at(names, end->other);
        list = scm_cons(with_sides ? scm_cons(name, side_symbol(end->side)) : name, list);
    }
    return list;
}

SCM standing_name(const Body& b, SCM names) {
    return b.standing_on > 0 ? name_at(names, static_cast<size_t>(b.standing_on - 1)) : SCM_BOOL_F;
}

namespace {

// `field`: the key's Field bit index, so that a cached entity whose key is
// placed is rewritten in one walk (rewrite_placed).
size_t report_edit(SCM old, SCM key, int8_t field, SCM value, Edit* edits, size_t n) {
    if (SCM_UNBNDP(value)) return n;
    const bool same = !SCM_UNBNDP(old) && scm_is_true(scm_equal_p(old, value));
    size_t k = 0;
    while (k < n && !scm_is_eq(edits[k].key, key)) ++k;
    if (k == n) {
        if (!same) edits[n++] = {key, value, false, field};
        return n;
    }
    if (!same) {
        edits[k].value = value;
        return n;
    }
    std::copy(edits + k + 1, edits + n, edits + k);  // keep the value the plist holds
    return n - 1;
}

}  // namespace

size_t report_edits(SCM entity, SCM touching, SCM standing, Edit* edits, size_t n) {
    const SCM old_touching = SCM_UNBNDP(touching) ? SCM_UNDEFINED : plist_get(entity, keys->key[kTouching], SCM_UNDEFINED);
    const SCM old_standing = SCM_UNBNDP(standing) ? SCM_UNDEFINED : plist_get(entity, keys->key[kStandingOn], SCM_UNDEFINED);
    return report_edits(old_touching, old_standing, touching, standing, edits, n);
}

size_t report_edits(SCM old_touching, SCM old_standing, SCM touching, SCM standing, Edit* edits, size_t n) {
    n = report_edit(old_touching, keys->key[kTouching], kFieldBitTouching, touching, edits, n);
    n = report_edit(old_standing, keys->key[kStandingOn], kFieldBitStandingOn, standing, edits, n);
    // A mark with no value to write (a key this call does not report).
    const Edit* end = std::remove_if(edits, edits + n, [](const Edit& e) { return scm_is_eq(e.value, SCM_UNSPECIFIED); });
    return static_cast<size_t>(end - edits);
}

SCM side_codes(std::span<const uint8_t> sides) {
    const SCM codes = scm_c_make_bytevector(sides.size());
    for (size_t k = 0; k < sides.size(); ++k)
        scm_c_bytevector_set_x(codes, k, static_cast<uint8_t>(sides[k] != 0 ? __builtin_ctz(sides[k]) : 0));
    return codes;
}

SCM pair_names(std::span<const IndexPair> pairs, SCM names) {
    SCM list = SCM_EOL;
    for (size_t k = pairs.size(); k-- > 0;)
        list = scm_cons(scm_cons(name_at(names, pairs[k].first), name_at(names, pairs[k].second)),
                        list);
    return list;
}

}  // namespace ds::guile
