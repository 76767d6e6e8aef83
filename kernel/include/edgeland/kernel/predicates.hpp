#pragma once
// Exact predicates and constructions on Point64 (thesis chapter 2). No floating point: every
// answer is a sign or a classification computed exactly in 128-bit integers.
// All functions require in-range points (point.hpp); they are O(1).
#include <cstdint>
#include <optional>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

enum class Orientation : std::int8_t { kClockwise = -1, kCollinear = 0, kCounterClockwise = 1 };

// Twice the signed area of triangle abc (exact). Inline: the clipper asks it millions of times
// per operation, and a call costs as much as the 128-bit arithmetic.
inline Int128 orient_det(Point64 a, Point64 b, Point64 c) noexcept {
  using D = arith::Checked<std::int64_t>;
  return formulas::orient_widening<D, arith::Checked<Int128>>(a.x, a.y, b.x, b.y, c.x, c.y).v;
}
// Which side of the directed line a->b the point c lies on (CCW = left).
inline Orientation orientation(Point64 a, Point64 b, Point64 c) noexcept {
  const Int128 d = orient_det(a, b, c);
  return static_cast<Orientation>((d > 0) - (d < 0));
}
// Sign of the dot product (b - a) . (c - a).
EDGELAND_EXPORT int dot_sign(Point64 a, Point64 b, Point64 c) noexcept;

// |b - a|^2, exact (formulas::dot_widening of b - a with itself). O(1).
EDGELAND_EXPORT Int128 squared_distance(Point64 a, Point64 b) noexcept;

// Whether p lies on the closed segment s (endpoints included). A degenerate segment
// (a == b) contains only its single point.
EDGELAND_EXPORT bool on_segment(Point64 p, const Segment& s) noexcept;
// Whether p lies on s strictly between its endpoints.
EDGELAND_EXPORT bool on_segment_interior(Point64 p, const Segment& s) noexcept;

// An exact rational point (x_num / den, y_num / den) with den > 0.
struct RationalPoint {
  Int128 x_num = 0;
  Int128 y_num = 0;
  Int128 den = 1;
  friend bool operator==(const RationalPoint&, const RationalPoint&) = default;
  bool is_integer() const noexcept { return x_num % den == 0 && y_num % den == 0; }
};

// Whether r is exactly the in-range integer point p: p * den == num per coordinate, without
// dividing (formulas::scaled; theorem scaled_int128 for |den| <= 2^95, far above the 2^67 of
// any intersection or ray point). O(1).
EDGELAND_EXPORT bool is_exactly(const RationalPoint& r, Point64 p) noexcept;

// How two closed segments meet.
enum class SegmentRelation : std::uint8_t {
  kDisjoint,     // no common point
  kCrossing,     // one common point, interior to both segments
  kTouching,     // one common point, an endpoint of at least one segment
  kOverlapping,  // collinear with a common part of positive length
};

struct SegmentIntersection {
  SegmentRelation relation = SegmentRelation::kDisjoint;
  // kCrossing: the exact crossing point (generally not an integer point).
  // kTouching: the common point (always an integer point: it is an endpoint).
  RationalPoint point;
  // kOverlapping: the common part, from its lexicographically smaller end to its larger one;
  // both are input endpoints, hence integer points.
  Point64 overlap_from;
  Point64 overlap_to;
};

// Classifies the pair of segments; degenerate segments (a == b) are treated as points.
EDGELAND_EXPORT SegmentIntersection intersect(const Segment& s, const Segment& t) noexcept;

// The exact intersection of the lines through s and t; nullopt when they are parallel.
EDGELAND_EXPORT std::optional<RationalPoint> line_intersection(const Segment& s,
                                                               const Segment& t) noexcept;

// THE rounding function of the library, and the only place an exact point becomes an
// integer point: each coordinate goes to the nearest integer, a tie (exactly .5) rounds up
// toward +infinity. Equivalently, the result is the integer point p whose half-open pixel
// [p.x - 1/2, p.x + 1/2) x [p.y - 1/2, p.y + 1/2) contains the rational point.
// The result of rounding an intersection of two in-range segments is in range.
EDGELAND_EXPORT Point64 round_to_grid(const RationalPoint& p) noexcept;

}  // namespace edgeland
