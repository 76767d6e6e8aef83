#pragma once
// Boolean operations on integer polygon sets (thesis chapter 3), closed under repetition:
// every result is a valid polygon set (kernel validate.hpp) and is accepted as input again.
//
// ACCURACY CONTRACT. For valid integer inputs the output differs from the exact real-number
// result R only by snap rounding (the kernel's round_to_grid, see clip/README.md):
//   * every output vertex lies within one unit of the boundary of the exact piece it belongs
//     to. Results are partitions (clip/README.md, Assembly): the pieces are, for a union, each
//     subject member and each clip member minus the subject; for an intersection or a
//     difference, each subject member's part; for xor, both differences; for normalize and
//     import_polygons, the filled region. So a vertex where two output polygons meet lies
//     near a member's boundary, which can be far inside R (a square united with a larger one
//     around it keeps the small square's corners, inside R); hole splitting cuts only between
//     vertices the pieces already have. (tests/support/accuracy_contract.hpp checks exactly
//     this, against CGAL's exact pieces.)
//   * |area(output) - area(R)| <= perimeter(R) (in coordinate units);
//   * every point farther than 1.5 units from the boundary of R is inside the output iff it
//     is inside R.
// LOCALITY. An input edge farther than 2 units from the other operand's boundary appears in
// the output unchanged, vertex for vertex, or not at all.
// CANONICAL OUTPUT. Polygons are hole-free, strictly simple and CCW, have no collinear
// consecutive vertices, start at their lexicographically smallest vertex and are sorted by
// that vertex; equal inputs give byte-identical outputs on every compiler and platform.
// ERRORS. Invalid input throws InvalidInput (nothing is returned half-done), the operand's
// first violation of validate(); two kinds are subclasses with fields of their own (errors.hpp):
// CoordinateOutOfRange for a coordinate beyond kCoordBound (polygon, ring, vertex, point), and
// InvalidBox for clip_to_box's box with min.x > max.x or min.y > max.y (the box; rule
// Rule::kInvertedBox). In checked mode every stage's result is checked before the next stage
// reads it (clip/src/stage_checks.hpp: fragments, plane graph, labels, rings), and every output
// is re-validated and its canonical form checked (canonical_form.hpp); a violation throws
// InternalError naming the stage and carrying the inputs as WKT.
// MEMORY. An operation's working memory peaks at about 90 bytes per input edge on smooth
// inputs (two circles of 2 * 10^5 vertices: 87), plus about 1,500 bytes per crossing when the
// crossings must be rounded (zigzag stars of 10^5 vertices each, 10^5 crossings: 1,450; snap
// rounding's hot pixels, routes and re-check). tests/clip/memory/memory_bound_test.cpp checks
// 120 per edge and 2,000 per crossing with a counting allocator. Each calling thread keeps the
// working arrays of its operations (edge list, search structures, plane graph, labels) in one
// scratch workspace and reuses them: allocating and freeing them per call made the allocator
// return them to the system and fault them in again every time, which cost more than the work.
// Arrays over 8 MiB are not kept but freed after the operation, and at most 16 arrays of each
// element type are kept; the rest is freed at thread exit.
// THREADS. Operations share no state between threads; concurrent calls are safe.
// HEADERS. This is the front end and includes types.hpp (ClipOp, FillRule, ClipOptions,
// ClipStats, ClipResult), valid_set.hpp (ValidSet, ValidClipResult) and errors.hpp
// (InternalError, InvalidOverlay), which code needing only those can include alone.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "edgeland/clip/errors.hpp"
#include "edgeland/clip/types.hpp"
#include "edgeland/clip/valid_set.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland {

// subject OP clip. Both must be valid polygon sets: an invalid one throws InvalidInput with
// validate()'s first violation, the subject's before the clip's. O((n + k) log n) for n input
// vertices and k intersections. The operands are validated by the operation itself, mostly
// for free (clip/README.md, "Validating while clipping"); the result is exactly the ValidSet
// overload's.
EDGELAND_EXPORT ClipResult clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clip,
                                const ClipOptions& options = {});

// The same operations on sets already known valid: no input validation; the result is a
// ValidSet for the next operation. Results are identical to the PolygonSet overloads'.
EDGELAND_EXPORT ValidClipResult clip(ClipOp op, const ValidSet& subject, const ValidSet& clip,
                                     const ClipOptions& options = {});
EDGELAND_EXPORT ValidClipResult clip_to_box(const ValidSet& set, const Box64& box,
                                            const ClipOptions& options = {});

// Any rings (self-intersecting, either orientation, overlapping, repeated points, spikes,
// zero-area parts) filled by `rule` -> a valid polygon set. Coordinates must be in range;
// rings with fewer than 3 distinct points contribute nothing. A coordinate beyond the bound
// throws CoordinateOutOfRange (operand kRings, polygon = the ring's index, ring 0).
EDGELAND_EXPORT ClipResult normalize(const std::vector<Ring>& rings, FillRule rule,
                                     const ClipOptions& options = {});

// OGC-style polygons with holes (element 0 of each entry is the exterior, the rest its holes;
// any ring orientation) -> a valid hole-free set: each exterior minus its holes, all members
// united. Each ring stands for the points it winds around (non-zero rule), so every lobe of a
// self-crossing ring counts (as with GEOS / PostGIS MakeValid); the result is where the sum of
// +1 per exterior and -1 per hole around a point is positive. For strictly simple rings this
// is normalize() with exteriors made CCW, holes CW and FillRule::kPositive, which is what runs
// then; the accuracy contract above holds against that exact region in every case.
// A coordinate beyond the bound throws CoordinateOutOfRange (operand kRings) naming the entry,
// the ring within it (0 the exterior, k hole k) and the vertex within that ring.
EDGELAND_EXPORT ClipResult import_polygons(const std::vector<std::vector<Ring>>& polygons,
                                           const ClipOptions& options = {});

// The same two imports with a ValidSet result, usable in the next operation without
// validating it again (identical polygons).
EDGELAND_EXPORT ValidClipResult normalize_to_valid_set(const std::vector<Ring>& rings,
                                                       FillRule rule,
                                                       const ClipOptions& options = {});
EDGELAND_EXPORT ValidClipResult import_to_valid_set(const std::vector<std::vector<Ring>>& polygons,
                                                    const ClipOptions& options = {});

// The same region as maximal polygons: members that touch along an edge become one polygon,
// and a region enclosing a hole is split along diagonals into hole-free polygons as every
// output is. Operations keep the subject's polygons apart (a union of two overlapping squares
// is 2 polygons: the subject's square and the clip's part outside it), which keeps edits
// local; a set that has grown through thousands of unions is merged to its fewest polygons
// and vertices by this. O(n log n); the result is normalize(set, kPositive)'s.
EDGELAND_EXPORT ValidClipResult merge(const ValidSet& set, const ClipOptions& options = {});

// merge()'s region for a set whose members tile it: the same maximal hole-free polygons up to
// where hole splitting cuts, found without noding, snap rounding or labeling (a valid set's
// members never cross; they meet at points and along shared stretches, which cancel). For
// sets that are mostly shared stretches, like a landscape's polygons of one material cut at
// cell lines: the game layer's debris outlines. Nothing rounds; the result's area is exactly the
// members' sum. O(n log n) plus hole splitting's bridges.
EDGELAND_EXPORT ValidClipResult merge_tiles(const ValidSet& set, const ClipOptions& options = {});

// merge_tiles() in two steps a caller can spread over two calls, a frame apart (a game's big
// debris): the constructor traces the union's boundary into rings (the stretches, their faces),
// finish() splits the holes and writes the pieces, returning exactly what merge_tiles() returns.
// ring_vertices() tells the second step's size. It owns what it keeps (no storage of the
// thread's scratch workspace), so it may live across frames.
class EDGELAND_EXPORT TileMerge {
 public:
  explicit TileMerge(const ValidSet& set, const ClipOptions& options = {});
  std::size_t ring_vertices() const noexcept;
  ValidClipResult finish() &&;

 private:
  std::vector<Ring> outers_, holes_;
  ClipOptions options_;
  Int128 twice_area_ = 0;  // the members', for checked mode
};

// The part of a valid set inside a closed axis-aligned box (the landscape's cell cut); a box
// of zero width or height gives the empty set. The box is the clip operand: a corner beyond
// the bound throws CoordinateOutOfRange (polygon 0, ring 0, vertex kNone, `where` the corner),
// an inverted box (min.x > max.x or min.y > max.y) InvalidBox; then the set is validated
// (operand kSubject). The ValidSet overload above checks the box the same way.
EDGELAND_EXPORT ClipResult clip_to_box(const PolygonSet& set, const Box64& box,
                                       const ClipOptions& options = {});

}  // namespace edgeland
