// Every tunable of the core in one place, each with the reason for its
// value (as Box2D keeps its constants.h). The rules' own numbers come first:
// they are part of the contract (docs/semantics.org), not tuning.
#pragma once
#include <cstddef>
#include <cstdint>

namespace ds {

// ---- the rules (semantics §1, §4): exported to Scheme under these names
constexpr double kGravity = 1.0;           // *gravity*, px/frame²
constexpr double kJumpForce = 15.0;        // *jump-force*
constexpr double kOnSolidTolerance = 4.0;  // *on-solid-tolerance*, px and px/frame

// ---- limits that refuse input
// Sub-frames per frame (make-game substeps:, step-scene #:substeps): beyond
// this a frame costs more than any game wants, and a typo such as 1e6 would
// hang the caller.
constexpr int kMaxSubsteps = 1024;

// ---- speed: each changes only how fast an answer comes, never the answer
// Bodies per block of the per-entity steps: 1024 × 168 B (172 KB) stays in
// L2 while all seven steps pass over it.
constexpr size_t kStepBlock = 1024;

// Below this many solid bodies, push-apart tries every pair: cheaper than
// building a grid for a handful.
constexpr size_t kPairGridFrom = 48;

// Below this many supporters, ground detection scans them all: cheaper than
// indexing a handful.
constexpr size_t kSupportIndexFrom = 32;

// A box spanning more grid cells than this on an axis is not filed in the
// push-apart grid or the support index: it is checked against every body
// (a floor under a crowd), which costs less than filing it in every cell.
constexpr int64_t kMaxFiledSpan = 8;

// A ground query spanning more columns than this scans the supporters
// instead of walking the index's cells.
constexpr int64_t kMaxQuerySpan = 64;

// Grids size their cells from the median of at most this many + 1 sampled
// boxes: any cell size gives the same answers, and a sample does as well as
// all of them while sparing a selection over 100 000 sizes every frame.
constexpr size_t kCellSizeSamples = 1024;

// A pair query (query.hpp) files a box under each grid cell it covers; one
// covering more than this many (a level-wide trigger among bullets) is tried
// against every box of the other set instead: filing it would cost more
// cells than the comparisons it saves.
constexpr uint64_t kQueryMaxCellsPerBox = 64;

// Cell indices are clamped to ±this: doubles beyond int64 lie outside any
// grid anyway, and the clamp keeps the conversion defined.
constexpr double kCellIndexLimit = 4.0e18;

}  // namespace ds
