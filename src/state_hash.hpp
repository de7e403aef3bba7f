// SPDX-License-Identifier: MIT
// A fingerprint of a scene's physical state, so that two runs (native and
// reference, live and replayed, this machine and another) can be compared
// frame by frame with one integer instead of whole entity lists.
//
// The hash is 64-bit FNV-1a (offset basis 0xcbf29ce484222325, prime
// 0x100000001b3; per byte: h ^= byte, then h *= prime mod 2^64) over this
// byte string, so it can be reproduced anywhere, in any language:
//
//   for each body, in sequence order (64 bytes per body, nothing else):
//     for each of x y w h vx vy ay, in that order (9 bytes each):
//       1 byte   exactness tag: 0x01 exact integer, 0x00 flonum
//       8 bytes  the IEEE-754 binary64 bits of the value, least significant
//                byte first; an exact value's -0.0 is written as +0.0
//                (exact zero has no sign), a flonum's sign of zero is kept
//     1 byte     on-ground flag: 0x01 true, 0x00 false
//
// A scene whose gravity (semantics §14) is not the seed's exact 1 appends,
// after its bodies, the byte 0x47 ('G') and the gravity as a number (9
// bytes, as above); at the default nothing is appended, so every scene's
// hash from before scene gravity existed is unchanged.
//
// The empty sequence hashes to the offset basis. Only these fields count:
// identity, flags other than on-ground, group data and anything a plist
// carries beyond them are not part of the physical state being compared.
// Bytes are produced explicitly, never copied from struct memory, so
// padding and host endianness cannot leak in.
#pragma once
#include <cstdint>
#include <span>

#include "body.hpp"
#include "export.hpp"

namespace ds {

constexpr uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;
constexpr uint64_t kFnvPrime = 0x100000001b3ull;

// Feeds bodies one at a time, for callers that decode them one at a time.
class DOWNSTROKE_API StateHash {
public:
    void add(const Body& body);
    // The scene's gravity, after the bodies: adds nothing at the default.
    void add_gravity(Num gravity);
    uint64_t value() const { return h_; }

private:
    void byte(uint8_t b) { h_ = (h_ ^ b) * kFnvPrime; }
    void number(Num n);

    uint64_t h_ = kFnvOffsetBasis;
};

DOWNSTROKE_API uint64_t state_hash(std::span<const Body> bodies);

}  // namespace ds
