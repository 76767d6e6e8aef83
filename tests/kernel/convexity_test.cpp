// convexity.hpp: is_convex (thesis 2.3), collinear vertices allowed, either orientation.
#include "edgeland/kernel/convexity.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "exact_reference.hpp"
#include "random_geometry.hpp"

namespace edgeland::test {
namespace {

Ring reversed(const Ring& r) { return Ring(r.rbegin(), r.rend()); }

TEST(IsConvex, FullRangeSquareEitherOrientation) {
  const Ring square{{-B, -B}, {B, -B}, {B, B}, {-B, B}};
  EXPECT_TRUE(is_convex(square));
  EXPECT_TRUE(is_convex(reversed(square)));
}

TEST(IsConvex, NearlyStraightVertexAtTheBoundIsStillATurn) {
  // (B-1, B) is one unit off the diagonal from (-B,-B) to (B,B): a real (tiny) turn.
  EXPECT_TRUE(is_convex(Ring{{-B, -B}, {B, B}, {B - 1, B}}));
  EXPECT_FALSE(is_convex(Ring{{-B, -B}, {B, B}, {B - 1, B}, {B, B - 1}}));
}

TEST(IsConvex, CollinearVertexOnAnEdgeIsAllowed) {
  // Thesis 2.1: interior angles "less or equal 180 degrees".
  EXPECT_TRUE(is_convex(Ring{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));
  EXPECT_TRUE(is_convex(Ring{{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}));  // straight at the end
}

TEST(IsConvex, ReflexVertexIsRejected) {
  EXPECT_FALSE(is_convex(Ring{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}));
}

TEST(IsConvex, FoldBackAndRepeatedVertexAreRejected) {
  EXPECT_FALSE(is_convex(Ring{{0, 0}, {2, 0}, {1, 0}, {1, 2}}));          // spike back along x
  EXPECT_FALSE(is_convex(Ring{{0, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}}));  // zero-length edge
}

TEST(IsConvex, PentagramWithAllLeftTurnsIsRejected) {
  // Every turn has the same sign, so the local test of thesis figure 7 alone would accept it;
  // the boundary winds around twice.
  const Ring star{{0, 10}, {-6, -8}, {10, 3}, {-10, 3}, {6, -8}};
  EXPECT_FALSE(is_convex(star));
  const Ring twice{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_FALSE(is_convex(twice));
}

TEST(IsConvex, DegenerateRingsAreRejected) {
  EXPECT_FALSE(is_convex(Ring{}));
  EXPECT_FALSE(is_convex(Ring{{0, 0}, {1, 1}}));
  EXPECT_FALSE(is_convex(Ring{{0, 0}, {1, 1}, {2, 2}}));
}

// Reference from the definition: a region of positive area with every vertex on the inner
// closed side of every edge's line, traversed once (|area| equals the hull's area).
bool ref_is_convex(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  const int s = sgn(ref_twice_area(ring));
  if (s == 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    if (a == b) return false;
    for (const Point64 v : ring) {
      if (sgn(ref_orient_det(a, b, v)) == -s) return false;
    }
  }
  return abs(ref_twice_area(ring)) == ref_twice_area(ref_convex_hull(ring));
}

RC_GTEST_PROP(IsConvexProperty, MatchesDefinitionOnRandomRings, ()) {
  const Ring ring = gen_ring(gen_grid(), 7);
  RC_ASSERT(is_convex(ring) == ref_is_convex(ring));
}

RC_GTEST_PROP(IsConvexProperty, AcceptsHullsWithCollinearVerticesEitherWay, ()) {
  const Ring ring = gen_convex_ring(gen_grid());
  RC_ASSERT(ref_is_convex(ring));
  RC_ASSERT(is_convex(ring));
  RC_ASSERT(is_convex(reversed(ring)));
}

}  // namespace
}  // namespace edgeland::test
