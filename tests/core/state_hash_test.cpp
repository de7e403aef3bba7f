// SPDX-License-Identifier: MIT
// ds::state_hash: FNV-1a 64 over the byte layout documented in
// state_hash.hpp. The expected values were computed independently (a few
// lines of Python: struct.pack('<d', v) per number), so these cases pin the
// layout itself, not just "some hash"; tests/scheme/determinism-test.scm pins
// the same values for the same scenes.
#include <vector>

#include "state_hash.hpp"
#include "support.hpp"

using namespace dst;
using ds::state_hash;

namespace {

// #:x 100 #:y 50 #:width 12 #:height 16 #:vx 3 #:vy -1.5 #:on-ground? #t
Body hero() {
    Body b = box(100, 50, 12, 16);
    b.vx = I(3);
    b.vy = F(-1.5);
    b.on_ground = true;
    return b;
}

// #:x 0.5 #:y -0.0 #:width 8 #:height 8
Body crate() {
    Body b = box(0, 0, 8, 8);
    b.x = F(0.5);
    b.y = F(-0.0);
    return b;
}

uint64_t hash_of(const Body& b) { return state_hash(std::span<const Body>(&b, 1)); }

}  // namespace

TEST_SUITE("state-hash") {

TEST_CASE("the empty sequence hashes to the FNV-1a offset basis") {
    CHECK(state_hash({}) == 14695981039346656037ull);
    CHECK(ds::StateHash{}.value() == ds::kFnvOffsetBasis);
}

TEST_CASE("pinned values for small inputs") {
    CHECK(hash_of(Body{}) == 15263143918111547514ull);
    CHECK(hash_of(hero()) == 17386948739817264273ull);
    CHECK(hash_of(crate()) == 10335750445336562271ull);
    const std::vector<Body> scene{hero(), crate()};
    CHECK(state_hash(scene) == 13637382024834548787ull);
}

TEST_CASE("the order of bodies matters") {
    const std::vector<Body> reversed{crate(), hero()};
    CHECK(state_hash(reversed) == 2856564895695392583ull);
}

TEST_CASE("feeding bodies one by one equals hashing the span") {
    ds::StateHash h;
    h.add(hero());
    h.add(crate());
    const std::vector<Body> scene{hero(), crate()};
    CHECK(h.value() == state_hash(scene));
}

TEST_CASE("exactness is part of the state: 103 is not 103.0") {
    Body exact, flonum;
    exact.x = I(103);
    flonum.x = F(103);
    CHECK(hash_of(exact) == 15969547569870839801ull);
    CHECK(hash_of(flonum) == 8199774132801132208ull);
}

TEST_CASE("a flonum keeps its sign of zero; an exact zero has none") {
    Body plus, minus, exact_minus;
    plus.x = F(0.0);
    minus.x = F(-0.0);
    exact_minus.x = I(-0.0);
    CHECK(hash_of(plus) == 10445826238564626127ull);
    CHECK(hash_of(minus) == 5536100258560081487ull);
    CHECK(hash_of(exact_minus) == hash_of(Body{}));
}

TEST_CASE("on-ground is hashed; identity and other flags are not") {
    Body grounded;
    grounded.on_ground = true;
    CHECK(hash_of(grounded) == 15263145017623175725ull);
    Body other;
    other.gravity = other.solid = other.immovable = other.group_origin = true;
    other.skip = ds::kSkipGravity;
    other.id = 7;
    other.group = 3;
    other.local_x = I(5);
    CHECK(hash_of(other) == hash_of(Body{}));
}

TEST_CASE("every hashed field changes the hash") {
    const uint64_t base = hash_of(hero());
    Num Body::*fields[] = {&Body::x, &Body::y, &Body::w, &Body::h, &Body::vx, &Body::vy, &Body::ay};
    for (Num Body::*field : fields) {
        Body b = hero();
        (b.*field).v += 1;
        CHECK(hash_of(b) != base);
    }
}

TEST_CASE("an exact integer past 2^53 hashes as its double") {
    Body b;
    b.x = I(18446744073709551616.0);  // 2^64
    CHECK(hash_of(b) == 10134489283689518977ull);
}

}  // TEST_SUITE
