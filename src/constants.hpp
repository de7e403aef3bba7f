// SPDX-License-Identifier: MIT
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
// A one-way cell holds a body up while its feet are less than this far below
// the cell's top (semantics §9). Not the tolerance above: a body that drops
// through a platform is 1 px or more into it after its first frame of
// falling (gravity makes vy at least 1), and must not stand there again.
constexpr double kOneWayFooting = 1.0;
// A stop rebounds (#:bounce, semantics §13) only faster than this, in px/frame:
// one frame of gravity. A body at rest on a floor hits it at exactly 1 every
// frame (gravity, then the snap back); it must stay at rest whatever its
// bounce, and a bouncing body whose rebounds decay comes to rest when they
// fall below it (Box2D's restitution threshold, for the same reason).
constexpr double kBounceRestSpeed = 1.0;
// Categories in one frame (#:category and every #:collides-with name,
// 'default included): a body's category and mask are one 64-bit word each.
constexpr int kMaxCategories = 64;

// ---- storage
// Tile-layer gids and solid-grid cells live in chunks of this many cells
// (a power of two: the hot cell read is a shift and a mask), shared between
// a map and its edited copies (shared_cells.hpp). An edit copies one chunk
// (4 KiB of grid, 16 KiB of gids) and a table of one pointer per chunk (245
// for a 1000² map); smaller chunks make that table, larger ones the chunk
// copy, the bigger cost.
constexpr int kCellChunkShift = 12;

// ---- limits that refuse input
// Distinct cell shapes (semantics §12) in one grid: a shape id is 16 bits per
// cell, beside the cell's kind byte. A map's shaped tiles times their eight
// flips stay far below it (a tileset of 1024 shaped tiles, all flipped, is
// 8192); more is a hostile or generated map and its load fails.
constexpr size_t kMaxGridShapes = 65535;

// Sub-frames per frame (make-game substeps:, step-scene #:substeps): beyond
// this a frame costs more than any game wants, and a typo such as 1e6 would
// hang the caller.
constexpr int kMaxSubsteps = 1024;

// ---- bounds on maps (load_tilemap, make_tilemap): each is the default of
// a MapLimits field or a fixed bound of the format, so a hostile file ends
// in an error naming it instead of exhausting memory.

// Tile-layer cells across the whole map (every layer, chunks included) and
// its solid grid's bounding box: 64 M cells. The largest Tiled maps people
// ship are a few layers of some thousand cells a side; 64 layers of 1024²,
// or one layer of 8192², fit. At 4 B per gid that is 256 MB of layers,
// about what a desktop game can spare, while a forged header asking for
// 64 layers of 4096² (4 GB) is refused before anything is allocated.
constexpr int64_t kMaxMapCells = int64_t{1} << 26;

// Bytes read for one map: the .tmx and every .tsx it names, together.
// tinyxml2 keeps about 20 bytes of DOM per byte of element-dense XML
// (measured: an 8.5 MB layer of <tile/> elements took 166 MB), so 64 MiB
// keeps a load near 1.3 GB at worst. Real maps are far smaller: the largest
// the cell bound admits fits when compressed (Tiled's zlib or zstd), and in
// CSV (about 5 B a cell) 64 MiB still holds 12 M cells.
constexpr int64_t kMaxMapBytes = int64_t{64} << 20;

// Tile width or height in px (map, tileset, make-tilemap). Cell edges are
// col × tile: with 2^24 px tiles even a map 2^26 cells wide ends within
// 2^50 px, well inside the 2^53 where doubles stop being exact. No art
// comes near it; make-tilemap has always refused more.
constexpr int64_t kMaxTileSize = int64_t{1} << 24;

// A tileset image's declared width or height, and its spacing and margin,
// in px: 65536, past every GPU's largest texture (16384–32768) and the SDL
// surfaces the renderer cuts tiles from. Keeps its int arithmetic
// (margin + col × (tile + spacing)) far from overflow.
constexpr int64_t kMaxImageSide = int64_t{1} << 16;

// Nested <group> layers: Tiled users nest a handful; the bound keeps the
// loader's recursion shallow whatever tinyxml2's own depth limit is.
constexpr int kMaxGroupDepth = 32;

// Class properties inside class (and list) properties: Tiled's own types
// nest a few levels; the bound keeps the loader's recursion shallow and a
// hostile file from building a deep chain of members.
constexpr int kMaxPropertyDepth = 32;

// Arrays and objects nested in a JSON map, tileset, template or project
// file. A map nests 2 levels per group layer (its "layers" array and the
// layer), so kMaxGroupDepth groups fit with room for class properties
// inside classes; the bound keeps the JSON readers' recursion shallow.
constexpr int kMaxJsonDepth = 4 * kMaxGroupDepth;

// Points of one collision polygon (a tileset tile's shape): the engine
// collides a convex polygon (at most kMaxShapeSlants slants on a side), and
// the real tilesets we read draw at most 10 points;
// 256 leaves room for outlines drawn with many points along their edges,
// while a forged polygon of 10^6 points is refused as its tileset is read.
constexpr size_t kMaxShapePoints = 256;

// How far past its tile a collision point may lie, in tiles (semantics
// §12): a shape drawn a little past its tile's edge collides as its part
// inside the cell, and one reaching more than a whole tile further is no
// tile's outline. Keeps the clip's exact integer arithmetic (products of
// two coordinates) far inside int64 and a ramp's slant points in int32.
constexpr int64_t kMaxShapeReachTiles = 1;

// Slanted edges of one cell shape (semantics §12): a convex polygon's upper
// boundary (a floor shape) or lower one (a ceiling shape) has a slant per
// edge that is neither horizontal nor vertical, kept inline in CellShape so
// a grid's table of shapes stays plain data. The real tilesets we read draw
// at most 10 points, so at most 4 slants on one side; 8 leaves room for a
// rounder hill, and a polygon with more collides as its whole cell, with a
// warning.
constexpr int kMaxShapeSlants = 8;

// Class members a Tiled project file fills into one map's properties (the
// defaults a map leaves out). A class whose members are classes multiplies
// at each level, so a hostile project of a few lines could ask for billions;
// real projects fill a few per object, and 262144 leaves room for maps with
// tens of thousands of objects while a refused fill stays near 40 MB.
constexpr int64_t kMaxFilledMembers = int64_t{1} << 18;

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
