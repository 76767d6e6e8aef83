// Bounded-exhaustive check of intersect() (predicates.hpp) against the rational reference
// (segment_reference.hpp) for every ordered pair of directed segments, degenerate ones
// included, on a 6x6 grid: the unit grid and a 6x6 grid spread over the whole coordinate
// range. For each pair: the relation; the common point (touching, crossing) as an exact
// rational with den > 0; the overlap's ends. For each crossing, also round_to_grid's rule:
// the rounded point R satisfies R - 1/2 <= x < R + 1/2 per axis and is in range.
#include <cstdio>
#include <string>
#include <vector>

#include "case_log.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "grids.hpp"
#include "segment_reference.hpp"

namespace edgeland::exhaustive {
namespace {

using boost::multiprecision::cpp_int;

cpp_int big(Int128 v) {  // exact, via two 64-bit halves
  const UInt128 u = unsigned_abs(v);
  cpp_int r = cpp_int(static_cast<std::uint64_t>(u >> 64)) << 64;
  r += static_cast<std::uint64_t>(u);
  return v < 0 ? cpp_int(-r) : r;
}

bool same_point(const RationalPoint& p, const RationalXY& ref) {
  return p.den > 0 && Rational(big(p.x_num), big(p.den)) == ref.x &&
         Rational(big(p.y_num), big(p.den)) == ref.y;
}

bool same_point(Point64 p, const RationalXY& ref) {
  return Rational(p.x) == ref.x && Rational(p.y) == ref.y;
}

bool agrees(const SegmentIntersection& got, const ReferenceIntersection& want) {
  if (got.relation != want.relation) return false;
  switch (want.relation) {
    case SegmentRelation::kDisjoint:
      return true;
    case SegmentRelation::kCrossing:
    case SegmentRelation::kTouching:
      return same_point(got.point, want.point);
    case SegmentRelation::kOverlapping:
      return same_point(got.overlap_from, want.from) && same_point(got.overlap_to, want.to);
  }
  return false;
}

// The rounding rule, checked on the reference value: R - 1/2 <= v < R + 1/2.
bool rounds_to(std::int64_t r, const Rational& v) {
  const Rational half(1, 2);
  return Rational(r) - half <= v && v < Rational(r) + half && coord_in_range(r);
}

std::string describe(const Segment& s, const Segment& t) {
  return str(s.a) + "-" + str(s.b) + " vs " + str(t.a) + "-" + str(t.b);
}

bool check_grid(const char* name, const std::vector<Point64>& pts) {
  std::vector<Segment> segments;
  for (Point64 a : pts) {
    for (Point64 b : pts) segments.push_back({a, b});
  }
  const std::string g = std::string(" [") + name + "]";
  CaseLog classify("intersect == rational reference" + g);
  CaseLog rounding("round_to_grid(crossing) is the nearest, halves up" + g);
  CaseLog symmetric("intersect(s, t) and intersect(t, s) agree on the relation" + g);
  for (const Segment& s : segments) {
    for (const Segment& t : segments) {
      const SegmentIntersection got = intersect(s, t);
      const ReferenceIntersection want = reference_intersect(s, t);
      classify.expect(agrees(got, want), [&] { return describe(s, t); });
      symmetric.expect(intersect(t, s).relation == got.relation, [&] { return describe(s, t); });
      if (want.relation == SegmentRelation::kCrossing && got.relation == want.relation) {
        const Point64 r = round_to_grid(got.point);
        rounding.expect(rounds_to(r.x, want.point.x) && rounds_to(r.y, want.point.y),
                        [&] { return describe(s, t) + " rounded to " + str(r); });
      }
    }
  }
  std::printf("%s: %zu points, %zu directed segments (%zu degenerate)\n", name, pts.size(),
              segments.size(), pts.size());
  const bool a = classify.report(), b = rounding.report(), c = symmetric.report();
  return a && b && c;
}

}  // namespace
}  // namespace edgeland::exhaustive

int main() {
  using namespace edgeland::exhaustive;
  const bool unit = check_grid("6x6 unit grid", grid(6));
  const bool wide = check_grid("6x6 over the full range", full_range_grid(6));
  return unit && wide ? 0 : 1;
}
