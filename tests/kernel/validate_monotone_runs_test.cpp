// The run sweep (kernel/src/validate_monotone_runs.hpp), validate()'s first try, driven
// directly with small run caps and no gates, so that tiny inputs are cut into many short runs
// and every pairing of runs is exercised; judged against the O(n^2) brute force of
// tests/support (written apart from the kernel).
//
// Soundness: kValid only for valid inputs, kInvalid only for invalid ones, kUndecided only
// when every ring passes its local rules. Completeness, where the path promises it: a valid
// input is kValid unless edges of two different rings meet (touching rings are left to the
// vertex sweep) or the work budget runs out (unlimited here).
#include "validate_monotone_runs.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "support/rc_grid_draws.hpp"
#include "support/validate_bruteforce.hpp"
#include "support/validate_generators.hpp"

namespace edgeland {
namespace {

using detail::RunVerdict;
using testing::validate_bruteforce;

constexpr std::int64_t B = kCoordBound;
constexpr std::uint32_t kCaps[] = {1, 2, 3, 5, 32};

RunVerdict run_verdict(const PolygonSet& set, std::uint32_t cap) {
  detail::RunSweepOptions options;
  options.run_cap = cap;
  options.min_edges_per_run = 0;     // always sweep, however short the runs
  options.work_per_edge = 1u << 30;  // never give up for work
  return detail::sweep_monotone_runs(set, {}, options);
}

__int128 orient(Point64 a, Point64 b, Point64 c) {
  return __int128(b.x - a.x) * (c.y - a.y) - __int128(b.y - a.y) * (c.x - a.x);
}

// Whether closed segments ab and cd share a point (independent of the kernel's predicates).
bool segments_meet(Point64 a, Point64 b, Point64 c, Point64 d) {
  const auto sgn = [](__int128 v) { return (v > 0) - (v < 0); };
  const int o1 = sgn(orient(a, b, c)), o2 = sgn(orient(a, b, d));
  const int o3 = sgn(orient(c, d, a)), o4 = sgn(orient(c, d, b));
  const auto on = [](Point64 p, Point64 q, Point64 r) {  // r on pq, given collinear
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
         (o4 == 0 && on(c, d, b));
}

// Whether an edge of one member meets an edge of another.
bool members_meet(const PolygonSet& set) {
  for (std::size_t i = 0; i < set.size(); ++i)
    for (std::size_t j = i + 1; j < set.size(); ++j)
      for (std::size_t a = 0; a < set[i].size(); ++a)
        for (std::size_t b = 0; b < set[j].size(); ++b) {
          const Segment e = ring_edge(set[i], a), f = ring_edge(set[j], b);
          if (segments_meet(e.a, e.b, f.a, f.b)) return true;
        }
  return false;
}

// Empty when the run sweep with this cap keeps its promises on `set` (file comment).
std::string broken_promise(const PolygonSet& set, std::uint32_t cap) {
  const RunVerdict verdict = run_verdict(set, cap);
  const testing::BruteForceFindings bf = validate_bruteforce(set);
  const std::string where = " (cap " + std::to_string(cap) + ")";
  switch (verdict) {
    case RunVerdict::kValid:
      return bf.ok() ? "" : "valid, but the brute force finds a violation" + where;
    case RunVerdict::kInvalid:
      return bf.ok() ? "invalid, but the brute force finds nothing" + where : "";
    case RunVerdict::kUndecided:
      // Every per-ring rule of the brute force is a local rule.
      if (!bf.ring_rules.empty()) {
        return std::string("undecided, but a local rule fails: ") +
               rule_name(std::get<0>(*bf.ring_rules.begin())) + where;
      }
      if (bf.ok() && !members_meet(set)) return "undecided on valid rings that never meet" + where;
      return "";
    case RunVerdict::kNotTried:
      return "not tried although every gate is off" + where;
  }
  return "unknown verdict";
}

void check_promises(const PolygonSet& set) {
  for (const std::uint32_t cap : kCaps) {
    const std::string why = broken_promise(set, cap);
    if (!why.empty()) RC_FAIL(why);
  }
}

using testing::grid_point;
using testing::grid_triangle;
using testing::RcDraw;

RC_GTEST_PROP(ValidateRunSweep, KeepsItsPromisesOnRandomRingsOfATinyGrid, ()) {
  const std::int64_t size = *rc::gen::element<std::int64_t>(2, 3, 4, 6, 10);
  const auto n = RcDraw{}(3, 14);
  Polygon ring;
  for (std::int64_t k = 0; k < n; ++k) ring.push_back(grid_point(size));
  check_promises({ring});
}

RC_GTEST_PROP(ValidateRunSweep, AcceptsStarShapedRingsAtAnyScale, ()) {
  RcDraw draw;
  const std::int64_t radius = *rc::gen::element<std::int64_t>(3, 20, 1 << 20, B / 2);
  const Ring star = testing::random_star(draw, Point64{draw(-B / 2, B / 2), draw(-B / 2, B / 2)},
                                         radius, static_cast<std::size_t>(draw(4, 60)));
  RC_ASSERT(!star.empty());
  for (const std::uint32_t cap : kCaps) RC_ASSERT(run_verdict({star}, cap) == RunVerdict::kValid);
  check_promises({star});
}

RC_GTEST_PROP(ValidateRunSweep, KeepsItsPromisesOnSetsOfStars, ()) {
  // Stars far apart, nested, overlapping or crossing: members that never touch are settled
  // by the run sweep alone (nesting by its point-in-polygon test).
  RcDraw draw;
  PolygonSet set;
  const auto count = draw(2, 5);
  for (std::int64_t k = 0; k < count; ++k) {
    Ring star = testing::random_star(draw, grid_point(60), draw(1, 30),
                                     static_cast<std::size_t>(draw(4, 24)));
    if (!star.empty()) set.push_back(star);
  }
  check_promises(set);
}

RC_GTEST_PROP(ValidateRunSweep, KeepsItsPromisesOnSetsOfTrianglesOnATinyGrid, ()) {
  const auto count = RcDraw{}(2, 6);
  PolygonSet set;
  for (std::int64_t k = 0; k < count; ++k) set.push_back(grid_triangle(4));
  check_promises(set);
}

RC_GTEST_PROP(ValidateRunSweep, KeepsItsPromisesOnPerturbedGridCellSets, ()) {
  RcDraw draw;
  const int cells = static_cast<int>(draw(1, 6));
  const std::int64_t cell = *rc::gen::element<std::int64_t>(2, 4);
  PolygonSet set = testing::random_grid_set(draw, cells, cell, Point64{0, 0});
  if (draw(0, 3) != 0 && !set.empty()) {
    Polygon& p = set[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(set.size())))];
    p[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(p.size())))] =
        grid_point(cells * cell);
  }
  check_promises(set);
}

RC_GTEST_PROP(ValidateRunSweep, KeepsItsPromisesAtTheCoordinateBound, ()) {
  static constexpr std::int64_t kValues[] = {-B, -B + 1, -1, 0, 1, B - 1, B};
  RcDraw draw;
  PolygonSet set;
  const auto count = draw(1, 4);
  for (std::int64_t k = 0; k < count; ++k) {
    Polygon p;
    const auto n = draw(3, 7);
    for (std::int64_t v = 0; v < n; ++v) p.push_back({kValues[draw(0, 7)], kValues[draw(0, 7)]});
    set.push_back(p);
  }
  check_promises(set);
}

// --- bounded-exhaustive -----------------------------------------------------------------

using testing::grid_points;

TEST(ValidateRunSweepExhaustive, EveryRingOfFiveVerticesOnA3x3Grid) {
  // 9^5 rings: folds, touching, collinear overlaps and crossings at every run cut.
  const std::vector<Point64> g = grid_points(3, 3);
  std::size_t valid = 0;
  testing::for_each_ring(g, 5, [&](const Ring& ring) {
    if (::testing::Test::HasFailure()) return;  // the first failure is enough
    const PolygonSet set{ring};
    for (const std::uint32_t cap : {1u, 2u, 32u})
      EXPECT_EQ(broken_promise(set, cap), "") << to_wkt(set);
    valid += run_verdict(set, 32) == RunVerdict::kValid;
  });
  EXPECT_GT(valid, 0u);
}

TEST(ValidateRunSweepExhaustive, EveryPairOfTrianglesOnA3x3Grid) {
  // Nesting, shared edges both ways, shared vertices, vertices on edges, crossings.
  const std::vector<Polygon> triangles = testing::grid_triangles(3, 3);
  ASSERT_EQ(triangles.size(), 76u);  // 84 triples less 8 collinear ones
  for (const Polygon& s : triangles)
    for (const Polygon& t : triangles)
      for (const std::uint32_t cap : {1u, 32u}) ASSERT_EQ(broken_promise({s, t}, cap), "");
}

// --- named cases -------------------------------------------------------------------------

Polygon square(std::int64_t x, std::int64_t y, std::int64_t side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

TEST(ValidateRunSweep, FindsARingInsideAnotherThatItNeverTouches) {
  for (const std::uint32_t cap : kCaps) {
    EXPECT_EQ(run_verdict({square(0, 0, 10), square(3, 3, 2)}, cap), RunVerdict::kInvalid);
    EXPECT_EQ(run_verdict({square(3, 3, 2), square(0, 0, 10)}, cap), RunVerdict::kInvalid);
    EXPECT_EQ(run_verdict({square(0, 0, 10), square(20, 3, 2)}, cap), RunVerdict::kValid);
  }
}

TEST(ValidateRunSweep, AcceptsARingInTheBoxButOutsideTheBodyOfAnother) {
  // A "C" open to the right with a square in its mouth: boxes nest, interiors do not.
  const Polygon c{{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 8}, {10, 8}, {10, 10}, {0, 10}};
  for (const std::uint32_t cap : kCaps) {
    EXPECT_EQ(run_verdict({c, square(4, 4, 2)}, cap), RunVerdict::kValid);
    EXPECT_EQ(run_verdict({square(4, 4, 2), c}, cap), RunVerdict::kValid);
  }
}

TEST(ValidateRunSweep, LeavesRingsSharingAnEdgeToTheVertexSweep) {
  // Neighbours sharing an edge are valid, but only the winding walk can tell.
  EXPECT_EQ(run_verdict({square(0, 0, 10), square(10, 0, 10)}, 32), RunVerdict::kUndecided);
  EXPECT_TRUE(validate(PolygonSet{square(0, 0, 10), square(10, 0, 10)}).ok());
  // Crossing members are invalid whatever else is true.
  EXPECT_EQ(run_verdict({square(0, 0, 10), square(5, 5, 10)}, 32), RunVerdict::kInvalid);
}

// A large smooth ring: the upper and lower halves of the integer disc of radius r (x strictly
// monotone along each half, so simple), counter-clockwise, 4r vertices.
Polygon integer_disc(std::int64_t r, Point64 center) {
  const auto isqrt = [](std::int64_t v) {
    std::int64_t s = 0;
    for (std::int64_t step = std::int64_t{1} << 20; step > 0; step >>= 1) {
      if ((s + step) * (s + step) <= v) s += step;
    }
    return s;
  };
  Polygon ring;
  for (std::int64_t x = r; x >= -r; --x)
    ring.push_back({center.x + x, center.y + isqrt(r * r - x * x)});
  for (std::int64_t x = -r + 1; x < r; ++x) {
    ring.push_back({center.x + x, center.y - isqrt(r * r - x * x)});
  }
  return ring;
}

TEST(ValidateRunSweep, HandsTouchingLargeRingsToTheVertexSweepWhichJudgesThem) {
  // Default options, as validate() runs it: touching members are undecided, and the vertex
  // sweep (told the local rules hold) must still accept a touch and reject an overlap.
  const Polygon a = integer_disc(50, {0, 0});
  const PolygonSet touching{a, integer_disc(50, {100, 0})};  // share the vertex (50 0)
  EXPECT_EQ(detail::sweep_monotone_runs(touching, {}), RunVerdict::kUndecided);
  EXPECT_TRUE(validate(touching).ok());
  const PolygonSet twice{a, a};  // every edge shared in the same direction
  EXPECT_EQ(detail::sweep_monotone_runs(twice, {}), RunVerdict::kUndecided);
  const ValidationReport report = validate(twice);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.violations.front().rule, Rule::kOverlappingInteriors);
}

TEST(ValidateRunSweep, SettlesLargeSmoothRingsAloneAndAgreesWithValidate) {
  const Polygon a = integer_disc(5000, {0, 0}), b = integer_disc(3000, {9000, 2000});
  EXPECT_EQ(detail::sweep_monotone_runs(PolygonSet{a}, {}), RunVerdict::kValid);
  EXPECT_EQ(detail::sweep_monotone_runs(PolygonSet{a, b}, {}), RunVerdict::kValid);
  EXPECT_TRUE(validate(PolygonSet{a, b}).ok());
  // Moved into the first disc: nested, found by the run sweep and by validate().
  const Polygon inner = integer_disc(1000, {100, -200});
  EXPECT_EQ(detail::sweep_monotone_runs(PolygonSet{a, inner}, {}), RunVerdict::kInvalid);
  EXPECT_FALSE(validate(PolygonSet{a, inner}).ok());
  // One vertex pushed across the far side of its own ring: a self-intersection.
  Polygon folded = a;
  folded[100] = {folded[100].x, -6000};
  EXPECT_EQ(detail::sweep_monotone_runs(PolygonSet{folded}, {}), RunVerdict::kInvalid);
  EXPECT_FALSE(validate(folded).ok());
}

}  // namespace
}  // namespace edgeland
