#pragma once
// The accuracy contract of clip.hpp as a test oracle. For an output S of the clipper and the
// exact real-number result R (cgal_reference.hpp):
//   1. S is a valid polygon set (kernel validate);
//   2. |area(S) - area(R)| <= perimeter(R), with perimeter(R) replaced by the integer upper
//      bound perimeter_ceil() (an exact bound, never a floating-point estimate); and
//      area(S) == area(R) exactly when the clipper reports that nothing was snapped;
//   3. every vertex of S lies within one unit of the exact boundary (squared distance <= 1).
//      "The exact boundary" is read as the boundary of the exact *pieces* of the output: the
//      clipper never merges subject polygons (clip/README.md, Assembly), so an output keeps
//      the internal edges between members, e.g. A1 and B1 - A in A union B. Their vertices
//      are exact and far from the boundary of R, but on the boundary of a piece;
//   4. every sample point farther than 1.5 from the boundary of R (exact squared distance
//      > 9/4) is in S iff it is inside R ("in S": in the closure of the union of the output
//      polygons, so that a point on an edge shared by two output pieces counts); when nothing
//      was snapped, every sample point is in the closure of S iff it is in the closure of R;
//   5. (derived from 4) S xor R lies within 1.5 of the boundary of R, so its area is at most
//      the area of that band: 3 perimeter(R) + (9/4) pi per boundary curve, pi < 22/7.
// Sample points: every integer and half-integer point of the box around inputs and output
// when there are few of them, otherwise random quarter-integer points in that box and near
// the input vertices (deterministic, seeded).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::test {

// The exact result of one operation: R, and a test for check 3 that is only asked about
// vertices farther than one unit from the boundary of R (it computes exact pieces lazily,
// only for the members near the vertex, so that large sets stay cheap).
struct ExactCase {
  ExactRegion result;
  // Whether v is within one unit of the boundary of one of the output's exact pieces.
  std::function<bool(Point64)> near_piece_boundary;
};

// R = a OP b; pieces per the operation table of clip/README.md: union keeps each subject
// member whole and adds each clip member minus the subject; intersection and difference
// act on each subject member; xor is both differences.
ExactCase exact_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b);
// The same with the operands' exact regions already at hand (ra = of(a), rb = of(b)).
ExactCase exact_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b, const ExactRegion& ra,
                     const ExactRegion& rb);
// R = set intersected with the closed box (pieces: each member intersected with the box).
ExactCase exact_clip_to_box(const PolygonSet& set, const Box64& box);
// A single exact region whose only piece is itself (normalize: one filled region).
ExactCase exact_region(const ExactRegion& region);

struct ContractOptions {
  bool symmetric_difference_bound = true;  // check 5 (one more CGAL operation)
  std::size_t dense_grid_limit = 6000;     // max half-integer points to test exhaustively
  std::size_t random_points = 300;         // otherwise: random points in the box ...
  std::size_t points_per_vertex = 2;       // ... and near each of up to 200 input vertices
  std::uint64_t seed = 0x5eed;
  // Output vertices for which check 3 is skipped (e.g. vertices known to be exact and far
  // from the change in a closure chain); evaluated before any exact distance.
  std::function<bool(Point64)> skip_vertex = nullptr;
};

struct ContractReport {
  std::string failure;            // empty when every check passed
  std::size_t points_tested = 0;  // sample points whose classification was compared
  bool ok() const { return failure.empty(); }
};

// Checks `out` against the exact case. `inputs` are the input vertices (sample points are
// placed around them); `context` is prepended to a failure message (e.g. the inputs as WKT).
ContractReport check_contract(const ExactCase& exact, const ClipResult& out,
                              const std::vector<Point64>& inputs, const std::string& context,
                              const ContractOptions& options = {});

// The whole oracle for clip(op, a, b): computes the exact case and checks `out`. The failure
// message names the operation and carries both inputs and the output as WKT.
ContractReport check_clip(ClipOp op, const PolygonSet& a, const PolygonSet& b,
                          const ClipResult& out, const ContractOptions& options = {});

// "ClipOp a b" as text with both operands in WKT, for messages.
std::string describe_case(ClipOp op, const PolygonSet& a, const PolygonSet& b);

}  // namespace edgeland::test
