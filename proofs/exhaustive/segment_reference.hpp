#pragma once
// An exact reference for segment-segment classification, written from the definitions with
// Boost.Multiprecision rationals (parametric forms and Cramer's rule), independently of the
// kernel: it shares no code with predicates.cpp.
#include <boost/multiprecision/cpp_int.hpp>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::exhaustive {

using Rational = boost::multiprecision::cpp_rational;

struct RationalXY {
  Rational x, y;
  friend bool operator==(const RationalXY&, const RationalXY&) = default;
};

struct ReferenceIntersection {
  SegmentRelation relation = SegmentRelation::kDisjoint;
  RationalXY point;     // kCrossing, kTouching: the one common point
  RationalXY from, to;  // kOverlapping: ends of the common part, lexicographic order
};

// The common points of the closed segments s and t (a degenerate segment is its point).
ReferenceIntersection reference_intersect(const Segment& s, const Segment& t);

// Whether p lies on the closed segment s.
bool reference_on_segment(Point64 p, const Segment& s);

}  // namespace edgeland::exhaustive
