// validate() on a set of more than 10^5 vertices: a 100 x 100 grid of cells sharing edges
// plus one star-shaped ring of 10^5 vertices. The sweep checks it all; the O(n^2) brute force
// confirms it on subsamples (windows of the grid, random edge pairs of the star) and confirms
// every violation the sweep reports once the set is broken.
#include <gtest/gtest.h>

#include <algorithm>

#include "edgeland/kernel/validate.hpp"
#include "support/validate_bruteforce.hpp"
#include "support/validate_generators.hpp"

namespace edgeland {
namespace {

using testing::bruteforce_segments_meet;
using testing::validate_bruteforce;

constexpr int kCells = 100;
constexpr std::int64_t kCell = 10;
constexpr std::size_t kStarVertices = 100'000;

struct LargeSet {
  PolygonSet set;
  std::size_t star = 0;  // index of the star
  std::size_t vertices = 0;
};

const LargeSet& large_set() {
  static const LargeSet large = [] {
    testing::SplitMixDraw draw(20261122);
    LargeSet l;
    l.set = testing::random_grid_set(draw, kCells, kCell, Point64{0, 0});
    // Far to the right of the grid, with radii from 1 to 10^8: a very spiky ring.
    l.set.push_back(
        testing::random_star(draw, Point64{1'000'000'000, 0}, 100'000'000, kStarVertices));
    l.star = l.set.size() - 1;
    for (const Polygon& p : l.set) l.vertices += p.size();
    return l;
  }();
  return large;
}

// The members whose vertices all lie in the window [x0, x0 + w] x [y0, y0 + w].
PolygonSet window(const PolygonSet& set, std::int64_t x0, std::int64_t y0, std::int64_t w) {
  PolygonSet out;
  for (const Polygon& p : set) {
    if (std::all_of(p.begin(), p.end(), [&](Point64 v) {
          return x0 <= v.x && v.x <= x0 + w && y0 <= v.y && v.y <= y0 + w;
        })) {
      out.push_back(p);
    }
  }
  return out;
}

TEST(ValidateLarge, SweepAcceptsGridAndStarOfMoreThan1e5Vertices) {
  const LargeSet& l = large_set();
  ASSERT_GE(l.vertices, 130'000u);
  ASSERT_GE(l.set[l.star].size(), 99'000u);  // a few parallel directions were merged
  const ValidationReport r = validate(l.set);
  EXPECT_TRUE(r.ok()) << r.violations.front().describe();
}

TEST(ValidateLarge, BruteForceAgreesOnWindowsOfTheGrid) {
  const LargeSet& l = large_set();
  testing::SplitMixDraw draw(7);
  for (int k = 0; k < 8; ++k) {
    const PolygonSet part =
        window(l.set, draw(0, kCells - 8) * kCell, draw(0, kCells - 8) * kCell, 8 * kCell);
    ASSERT_GE(part.size(), 20u);
    EXPECT_TRUE(validate_bruteforce(part).ok());
    EXPECT_TRUE(validate(part).ok());
  }
}

TEST(ValidateLarge, BruteForceFindsNoContactBetweenRandomEdgesOfTheStar) {
  const Polygon& star = large_set().set[large_set().star];
  const auto n = static_cast<std::int64_t>(star.size());
  testing::SplitMixDraw draw(11);
  for (int k = 0; k < 200'000; ++k) {
    const auto i = draw(0, n), j = draw(0, n);
    const auto gap = (j - i + n) % n;
    if (gap <= 1 || gap == n - 1) continue;  // adjacent edges share a vertex
    const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
    ASSERT_FALSE(bruteforce_segments_meet(star[a], star[(a + 1) % star.size()], star[b],
                                          star[(b + 1) % star.size()]));
  }
}

TEST(ValidateLarge, EveryViolationOfABrokenLargeSetIsConfirmed) {
  PolygonSet set = large_set().set;
  const std::size_t star = large_set().star;
  // A grid member in the middle pushed 3 units up and right, over its neighbours.
  const auto middle = std::find_if(set.begin(), set.end(), [](const Polygon& p) {
    return p.front().x >= 50 * kCell && p.front().y >= 50 * kCell;
  });
  ASSERT_NE(middle, set.end());
  const auto moved = static_cast<std::size_t>(middle - set.begin());
  for (Point64& v : *middle) v = {v.x + 3, v.y + 3};
  // A star vertex pulled through the centre to the far side: its edges cut the ring.
  Polygon& s = set[star];
  s[s.size() / 3] = {2 * 1'000'000'000 - s[s.size() / 3].x, -s[s.size() / 3].y};

  // A few violations are enough: each overlap after the first costs one more full sweep.
  const ValidationReport r = validate(set, 6);
  ASSERT_FALSE(r.ok());
  bool star_found = false, moved_found = false;
  const PolygonSet near = window(set, 47 * kCell, 47 * kCell, 7 * kCell);
  const testing::BruteForceFindings bf = validate_bruteforce(near);
  for (const Violation& v : r.violations) {
    if (v.rule == Rule::kSelfIntersection) {
      ASSERT_EQ(v.polygon, star);
      star_found = true;
      const std::size_t n = s.size();
      EXPECT_NE((v.edge + 1) % n, v.other_edge);
      EXPECT_NE((v.other_edge + 1) % n, v.edge);
      EXPECT_TRUE(bruteforce_segments_meet(s[v.edge], s[(v.edge + 1) % n], s[v.other_edge],
                                           s[(v.other_edge + 1) % n]));
      continue;
    }
    ASSERT_EQ(v.rule, Rule::kOverlappingInteriors) << v.describe();
    moved_found = moved_found || v.polygon == moved || v.other_polygon == moved;
    // Both members lie in the window around the moved one: the brute force must agree.
    const auto in_near = [&](std::size_t i) {
      return std::find(near.begin(), near.end(), set[i]) - near.begin();
    };
    const auto a = static_cast<std::size_t>(in_near(v.polygon));
    const auto b = static_cast<std::size_t>(in_near(v.other_polygon));
    ASSERT_LT(a, near.size());
    ASSERT_LT(b, near.size());
    EXPECT_TRUE(bf.overlaps.count({std::min(a, b), std::max(a, b)})) << v.describe();
  }
  EXPECT_TRUE(star_found);
  EXPECT_TRUE(moved_found);
  EXPECT_FALSE(bf.overlaps.empty());
}

}  // namespace
}  // namespace edgeland
