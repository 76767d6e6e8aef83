#pragma once
// The exact reference of the clipper tests: regions of the plane computed by CGAL 5.5's
// Boolean_set_operations_2 over Exact_predicates_exact_constructions_kernel. Every answer is
// exact: areas are rationals, perimeters are safe integer upper bounds computed from exact
// squared lengths, and distance questions compare exact squared distances.
//
// CGAL itself lives only in cgal_reference.cpp: one translation unit with the Boolean
// operations takes ~40 s and >1 GB to compile (TOOLCHAIN.md pitfall 7), so this header exposes
// an opaque handle and GMP rationals (boost::multiprecision::mpq_rational, which is also
// CGAL's exact number type here) and nothing of CGAL.
#include <boost/multiprecision/gmp.hpp>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::test {

using Rational = boost::multiprecision::mpq_rational;
using BigInt = boost::multiprecision::mpz_int;

struct QPoint {
  Rational x, y;
};
inline QPoint to_q(Point64 p) { return {Rational(p.x), Rational(p.y)}; }

// A closed regularised region of the plane: a finite union of polygons with holes whose
// vertices are rational points. Immutable; copies share their representation.
class ExactRegion {
 public:
  ExactRegion();  // the empty region

  // The union of the members (for a valid set: the members side by side).
  static ExactRegion of(const PolygonSet& set);
  static ExactRegion of(const Polygon& polygon);
  // The union of simple polygons with rational vertices, in either orientation; consecutive
  // repeated vertices are ignored, and pieces with fewer than 3 distinct vertices or zero area
  // contribute nothing. Used to build the normalize() reference from trapezoids.
  static ExactRegion of_rational_polygons(const std::vector<std::vector<QPoint>>& polygons);

  // this OP other, computed exactly (kXor is CGAL's symmetric_difference).
  ExactRegion apply(ClipOp op, const ExactRegion& other) const;

  bool empty() const;
  Rational area() const;
  // An integer >= the length of the boundary (outer boundaries and holes): the sum over the
  // boundary edges of ceil(length), each computed exactly from the rational squared length.
  BigInt perimeter_ceil() const;
  // Number of closed boundary curves (outer boundaries plus holes).
  std::size_t boundary_cycles() const;
  std::size_t boundary_edges() const;

  enum class Location { kInside, kOnBoundary, kOutside };
  // By the parity of crossings with the boundary curves (exact). O(boundary edges).
  Location locate(const QPoint& p) const;
  // CGAL's own Polygon_set_2::oriented_side, kept to document its disagreement (see .cpp).
  Location locate_by_cgal(const QPoint& p) const;
  // Whether the boundary has a point q with |p - q|^2 <= squared_radius (exact).
  bool boundary_within(const QPoint& p, const Rational& squared_radius) const;

  // The polygons with holes as text, rational coordinates written n/d, for failure messages.
  std::string to_text() const;

 private:
  struct Impl;
  explicit ExactRegion(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

// How often, since the program started, the oracle had to get past a failure of CGAL 5.5 (see
// cgal_reference.cpp), by the way the answer was then computed - each as exact as the first.
struct OracleFallbacks {
  std::size_t rebuilt = 0;            // an operation redone on sets rebuilt from their polygons
  std::size_t split = 0;              // ... as the union of its halves either side of a line
  std::size_t part_by_part = 0;       // ... one polygon with holes of an operand at a time
  std::size_t members_in_halves = 0;  // a set's members joined as two groups, then united
};
OracleFallbacks oracle_fallbacks();

// Test hook: while an object lives, the oracle on this thread behaves as if CGAL had failed in
// its first attempts, so that a fallback computes the answer (which must be the same region):
// apply() skips the operation on the sets as they are (kDirect), also the one on rebuilt sets
// (kDirectAndRebuilt), or goes straight to part by part (kPartByPart); and of() always joins
// the members in two halves.
class ForcedOracleFallback {
 public:
  enum class Skip { kDirect = 1, kDirectAndRebuilt = 2, kPartByPart = 3 };
  explicit ForcedOracleFallback(Skip skip);
  ~ForcedOracleFallback();
  ForcedOracleFallback(const ForcedOracleFallback&) = delete;
  ForcedOracleFallback& operator=(const ForcedOracleFallback&) = delete;

 private:
  int previous_;
};

// Exact squared distance between two closed segments with integer endpoints (a segment with
// a == b is a point), compared with a rational: whether it is > squared_radius.
bool segments_farther_than(const Segment& s, const Segment& t, const Rational& squared_radius);

}  // namespace edgeland::test
