// The sweep of validate() against the O(n^2) brute force of tests/support (written apart from
// the kernel): RapidCheck properties on random valid inputs and on the same inputs broken on
// purpose, and bounded-exhaustive runs over every small ring and triangle set of tiny grids.
//
// Agreement means: the same ok() verdict; the same per-ring findings (rule, polygon, index)
// for every rule the sweep reports in full; the same rings found self-intersecting, every
// reported edge pair confirmed; overlaps found iff there are any, every reported pair
// confirmed (one sweep finds one pair, then drops its later member and looks again).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <tuple>

#include "edgeland/kernel/validate.hpp"
#include "support/rc_grid_draws.hpp"
#include "support/validate_bruteforce.hpp"
#include "support/validate_generators.hpp"

namespace edgeland {
namespace {

using testing::grid_point;
using testing::grid_triangle;
using testing::RcDraw;
using testing::validate_bruteforce;

constexpr std::int64_t B = kCoordBound;
constexpr std::size_t kAll = 1'000'000;

// Empty when the sweep and the brute force agree on `set` (see the file comment), else why not.
std::string disagreement(const PolygonSet& set) {
  const ValidationReport sweep = validate(set, kAll);
  const testing::BruteForceFindings bf = validate_bruteforce(set);
  if (sweep.ok() != bf.ok())
    return sweep.ok() ? "sweep finds nothing" : "brute force finds nothing";

  std::set<std::tuple<Rule, std::size_t, std::size_t>> ring_rules;
  std::set<std::size_t> self_intersecting, bf_self_intersecting;
  bool overlap = false;
  for (const Violation& v : sweep.violations) {
    if (v.rule == Rule::kSelfIntersection) {
      self_intersecting.insert(v.polygon);
      if (bf.self_intersections.count({v.polygon, v.edge, v.other_edge}) == 0) {
        return "not confirmed: " + v.describe();
      }
    } else if (v.rule == Rule::kOverlappingInteriors) {
      overlap = true;
      if (bf.overlaps.count({v.polygon, v.other_polygon}) == 0) {
        return "not confirmed: " + v.describe();
      }
    } else {
      ring_rules.emplace(v.rule, v.polygon, v.edge);
    }
  }
  for (const auto& [p, e, f] : bf.self_intersections) bf_self_intersecting.insert(p);
  if (ring_rules != bf.ring_rules) return "per-ring rules differ";
  if (self_intersecting != bf_self_intersecting) return "self-intersecting rings differ";
  if (overlap == bf.overlaps.empty()) return overlap ? "overlap not confirmed" : "overlap missed";
  return {};
}

void check_agrees(const PolygonSet& set) {
  const std::string why = disagreement(set);
  if (!why.empty()) RC_FAIL(why);
}

// The same set turned a quarter turn, or mirrored with every ring reversed to stay
// counter-clockwise: validity does not depend on the sweep direction.
PolygonSet turned(PolygonSet set, bool mirror) {
  for (Polygon& p : set) {
    for (Point64& v : p) v = mirror ? Point64{-v.x, v.y} : Point64{-v.y, v.x};
    if (mirror) std::reverse(p.begin(), p.end());
  }
  return set;
}

void check_agrees_in_every_direction(const PolygonSet& set) {
  check_agrees(set);
  check_agrees(turned(set, false));
  check_agrees(turned(set, true));
}

// Coordinates that stress the bound: both ends of the range and the middle.
std::int64_t extreme_coordinate() {
  static constexpr std::int64_t kValues[] = {-B, -B + 1, -1, 0, 1, B - 1, B};
  return kValues[RcDraw{}(0, 7)];
}

// Breaks (or, sometimes, harmlessly rearranges) a set: duplicate, flip, move a vertex onto
// another one's edge or anywhere, nest a star, shift a member, insert or drop a vertex.
void perturb(PolygonSet& set, std::int64_t extent) {
  RcDraw draw;
  if (set.empty()) return;
  Polygon& p = set[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(set.size())))];
  if (p.empty()) return;
  const auto n = static_cast<std::int64_t>(p.size());
  const auto i = static_cast<std::size_t>(draw(0, n));
  switch (draw(0, 9)) {
    case 0:  // identical member, maybe starting at another vertex
      set.push_back(p);
      std::rotate(set.back().begin(), set.back().begin() + draw(0, n), set.back().end());
      break;
    case 1:
      std::reverse(p.begin(), p.end());
      break;
    case 2:
      p[i] = grid_point(extent);
      break;
    case 3: {  // a vertex onto another member's vertex or edge midpoint (when integer)
      const Polygon& q =
          set[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(set.size())))];
      if (q.empty()) break;
      const auto j = static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(q.size())));
      const Point64 a = q[j], b = q[(j + 1) % q.size()];
      const bool mid = draw(0, 2) == 0 && (a.x + b.x) % 2 == 0 && (a.y + b.y) % 2 == 0;
      p[i] = mid ? Point64{(a.x + b.x) / 2, (a.y + b.y) / 2} : a;
      break;
    }
    case 4: {
      RcDraw d;
      Ring star = testing::random_star(d, grid_point(extent), draw(1, 4),
                                       static_cast<std::size_t>(draw(4, 9)));
      if (!star.empty()) set.push_back(star);
      break;
    }
    case 5: {
      const Point64 shift{draw(-2, 3), draw(-2, 3)};
      for (Point64& v : p) v = {v.x + shift.x, v.y + shift.y};
      break;
    }
    case 6:
      p.insert(p.begin() + static_cast<std::ptrdiff_t>(i) + 1, grid_point(extent));
      break;
    case 7:
      p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    default:
      std::rotate(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(i), p.end());
      break;
  }
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, RandomRingsOnATinyGrid, ()) {
  // Mostly broken rings: every rule, and the degenerate contacts a 5x5 grid forces.
  const std::int64_t size = *rc::gen::element<std::int64_t>(2, 3, 4, 6);
  const auto n = RcDraw{}(0, 20) == 0 ? RcDraw{}(0, 3) : RcDraw{}(3, 12);
  Polygon ring;
  for (std::int64_t k = 0; k < n; ++k) ring.push_back(grid_point(size));
  check_agrees_in_every_direction({ring});
  RC_ASSERT(validate(ring, kAll).violations.size() ==
            validate(PolygonSet{ring}, kAll).violations.size());
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, StarShapedRingsAreValid, ()) {
  RcDraw draw;
  const std::int64_t radius = *rc::gen::element<std::int64_t>(3, 20, 1 << 20, B / 2);
  const Ring star = testing::random_star(draw, Point64{draw(-B / 2, B / 2), draw(-B / 2, B / 2)},
                                         radius, static_cast<std::size_t>(draw(4, 40)));
  RC_ASSERT(!star.empty());
  RC_ASSERT(validate(star).ok());
  check_agrees({star});
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, SetsOfTrianglesOnATinyGrid, ()) {
  // Touching, sharing edges, nesting and crossing all happen on a 4x4 grid.
  const auto count = RcDraw{}(2, 6);
  PolygonSet set;
  for (std::int64_t k = 0; k < count; ++k) set.push_back(grid_triangle(4));
  check_agrees_in_every_direction(set);
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, GreedilyPackedTrianglesAreValid, ()) {
  // Triangles kept only when the brute force accepts the grown set: valid sets dense with
  // shared edges, vertices on edges and vertices shared by many members.
  const std::int64_t size = *rc::gen::element<std::int64_t>(2, 3, 4);
  PolygonSet set;
  for (int attempt = 0; attempt < 12; ++attempt) {
    set.push_back(grid_triangle(size));
    if (!validate_bruteforce(set).ok()) set.pop_back();
  }
  RC_ASSERT(validate(set).ok());
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, GridCellSetsAreValid, ()) {
  RcDraw draw;
  const int cells = static_cast<int>(draw(1, 7));
  const std::int64_t cell = *rc::gen::element<std::int64_t>(1, 2, 4);
  const PolygonSet set =
      testing::random_grid_set(draw, cells, cell, Point64{draw(-5, 5), draw(-5, 5)});
  RC_ASSERT(validate(set).ok());
  check_agrees_in_every_direction(set);
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, PerturbedGridCellSets, ()) {
  RcDraw draw;
  const int cells = static_cast<int>(draw(1, 6));
  const std::int64_t cell = *rc::gen::element<std::int64_t>(2, 4);
  PolygonSet set = testing::random_grid_set(draw, cells, cell, Point64{0, 0});
  const auto changes = draw(1, 4);
  for (std::int64_t k = 0; k < changes; ++k) perturb(set, cells * cell);
  check_agrees_in_every_direction(set);
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, RingsAndSetsAtTheCoordinateBound, ()) {
  RcDraw draw;
  PolygonSet set;
  const auto count = draw(1, 5);
  for (std::int64_t k = 0; k < count; ++k) {
    Polygon p;
    const auto n = draw(3, 6);
    for (std::int64_t v = 0; v < n; ++v) p.push_back({extreme_coordinate(), extreme_coordinate()});
    set.push_back(p);
  }
  check_agrees_in_every_direction(set);
}

RC_GTEST_PROP(ValidateSweepVsBruteForce, GridSetsSpanningTheWholeRange, ()) {
  // Cells of side 2B / cells from -B: the largest coordinates the kernel accepts.
  RcDraw draw;
  const int cells = static_cast<int>(draw(1, 5));
  const std::int64_t cell = (2 * B / cells) & ~std::int64_t{1};
  PolygonSet set = testing::random_grid_set(draw, cells, cell, Point64{-B, -B});
  RC_ASSERT(validate(set).ok());
  if (draw(0, 2) == 0) {
    // Move one vertex by a single unit: overlap or a gap, decided at full magnitude.
    Polygon& p = set[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(set.size())))];
    Point64& v = p[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(p.size())))];
    v = {std::clamp<std::int64_t>(v.x + draw(-1, 2), -B, B),
         std::clamp<std::int64_t>(v.y + draw(-1, 2), -B, B)};
  }
  check_agrees_in_every_direction(set);
}

// --- bounded-exhaustive cross-checks ------------------------------------------------------

using testing::grid_points;

TEST(ValidateExhaustive, EveryRingOfFourVerticesOnA3x3Grid) {
  const std::vector<Point64> g = grid_points(3, 3);
  std::size_t rings = 0, valid = 0;
  for (const Point64 a : g)
    for (const Point64 b : g)
      for (const Point64 c : g)
        for (const Point64 d : g) {
          const PolygonSet set{{a, b, c, d}};
          ASSERT_EQ(disagreement(set), "") << a.x << a.y << b.x << b.y << c.x << c.y << d.x << d.y;
          ++rings;
          valid += validate(set).ok();
        }
  EXPECT_EQ(rings, 6561u);
  EXPECT_GT(valid, 0u);
}

TEST(ValidateExhaustive, EveryRingOfFiveVerticesOnA3x2Grid) {
  const std::vector<Point64> g = grid_points(3, 2);
  std::size_t rings = 0;
  testing::for_each_ring(g, 5, [&](const Ring& ring) {
    if (::testing::Test::HasFailure()) return;  // the first failure is enough
    EXPECT_EQ(disagreement(turned(PolygonSet{ring}, false)), "");
    ++rings;
  });
  EXPECT_EQ(rings, 7776u);
}

using testing::grid_triangles;

TEST(ValidateExhaustive, EveryPairOfTrianglesOnA3x3Grid) {
  // Each triangle against every one, itself included: nesting, shared edges both ways, shared
  // vertices, vertices on edges, crossings.
  const std::vector<Polygon> triangles = grid_triangles(3, 3);
  ASSERT_EQ(triangles.size(), 76u);  // 84 triples less 8 collinear ones
  std::size_t valid_pairs = 0;
  for (const Polygon& s : triangles)
    for (const Polygon& t : triangles) {
      const PolygonSet set{s, t};
      ASSERT_EQ(disagreement(set), "");
      ASSERT_EQ(disagreement(turned(set, true)), "");
      valid_pairs += validate(set).ok();
    }
  EXPECT_GT(valid_pairs, 0u);
}

TEST(ValidateExhaustive, EveryTripleOfTrianglesOnA3x2Grid) {
  // Three members: after one overlapping pair is reported, the re-sweep without its later
  // member must still find (or not) the rest.
  const std::vector<Polygon> triangles = grid_triangles(3, 2);
  ASSERT_EQ(triangles.size(), 18u);  // 20 triples less 2 collinear rows
  for (const Polygon& s : triangles)
    for (const Polygon& t : triangles)
      for (const Polygon& u : triangles) ASSERT_EQ(disagreement({s, t, u}), "");
}

}  // namespace
}  // namespace edgeland
