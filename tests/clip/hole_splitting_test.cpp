// Hole splitting (clip/src/hole_splitting.hpp): split_holes on the regions with holes that
// assemble hands it (random operands, difference and xor; with and without corner bridges) and
// on hand-made regions. The pieces must be valid polygons (strictly simple, counter-clockwise,
// so hole-free) with disjoint interiors, lie in the region (just inside each piece edge the
// region's rings wind once: outers +1, holes -1), leave no region vertex strictly inside a
// piece, have areas summing exactly to the outers' minus the holes', and use only vertices of the
// region's rings (bridges end at vertices). holes_split grows by the number of holes.
#include "hole_splitting.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "assembly.hpp"
#include "canonical.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/validate.hpp"
#include "generators.hpp"
#include "stage_inputs.hpp"

namespace edgeland::test {
namespace {

// The first violation of split_holes' contract on one region, or "".
std::string split_problems(const std::vector<Ring>& outers, const std::vector<Ring>& holes) {
  std::size_t holes_split = 3;  // added to, not reset
  const std::vector<Ring> pieces = detail::split_holes(outers, holes, holes_split);
  if (holes_split != 3 + holes.size()) return "holes_split does not grow by the number of holes";
  std::set<Point64> vertices;
  std::vector<Segment> segments;
  std::vector<Ring> region = outers;
  region.insert(region.end(), holes.begin(), holes.end());
  Int128 want = 0;
  for (const Ring& r : region) {
    want += twice_signed_area(r);
    vertices.insert(r.begin(), r.end());
    for (std::size_t i = 0; i < r.size(); ++i) segments.push_back(ring_edge(r, i));
  }
  Int128 got = 0;
  for (const Ring& p : pieces) {
    if (!validate(p, 1).ok())
      return "a piece is not a valid polygon: " + validate(p, 1).violations[0].describe();
    got += twice_signed_area(p);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!vertices.count(p[i]))
        return "piece vertex " + stages::str(p[i]) + " is no vertex of the region";
      segments.push_back(ring_edge(p, i));
    }
  }
  if (got != want) return "the pieces' areas do not sum to the region's";
  if (!validate(pieces, 1).ok())
    return "pieces overlap: " + validate(pieces, 1).violations[0].describe();
  // Inside the region just left of every piece edge; no region vertex strictly inside a piece.
  const stages::SideProbe probe(stages::reach_of(segments));
  std::vector<Ring> scaled_region;
  for (const Ring& r : region) scaled_region.push_back(probe.scaled(r));
  for (const Ring& p : pieces) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Point64 q = probe.left_of(p[i], p[(i + 1) % p.size()]);
      int winding = 0;
      for (const Ring& r : scaled_region) winding += winding_number(q, r);
      if (winding != 1) return "a piece reaches out of the region at " + stages::str(p[i]);
    }
    for (Point64 v : vertices)
      if (locate(v, p) == PointLocation::kInside)
        return "region vertex " + stages::str(v) + " inside a piece";
  }
  return "";
}

RC_GTEST_PROP(HoleSplitting, PiecesTileTheRegionWithHoleFreePolygons, ()) {
  // A shape with smaller shapes inside and around it; the difference (or xor) has holes.
  const std::int64_t r = *rc::gen::element<std::int64_t>(6, 10, 16, 30);
  const Point64 c{*gen::coord(-2, 2), *gen::coord(-2, 2)};
  const PolygonSet outer = {*gen::shape(c, r)};
  const PolygonSet inner = *rc::gen::oneOf(gen::polygon_set(c, r / 2), gen::polygon_set(c, r));
  const bool corner_bridges = (stages::uniform(0, 1) == 1);
  const stages::Arrangement a(outer, inner, true);
  std::vector<detail::SideState> left;
  RC_ASSERT(detail::label_sides(a.graph, detail::LabelMode::kOwner, left));
  const detail::Assembled out = detail::assemble(
      a.graph, left,
      detail::LabelOf::operation(*rc::gen::element(ClipOp::kDifference, ClipOp::kXor)), false,
      corner_bridges);
  RC_PRE(!out.holed.empty());
  std::size_t holes = 0;
  for (const detail::RegionRings& region : out.holed) holes += region.holes.size();
  RC_CLASSIFY(holes > 1, "several holes");
  for (const detail::RegionRings& region : out.holed)
    RC_ASSERT(split_problems(std::vector<Ring>(region.outers.begin(), region.outers.end()),
                             std::vector<Ring>(region.holes.begin(), region.holes.end())) ==
              std::string());
}

// ---- hand-made regions ---------------------------------------------------------------------

Ring cw(Ring r) { return Ring(r.rbegin(), r.rend()); }
Ring rect(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

TEST(HoleSplitting, SquareWithOneHole) {
  EXPECT_EQ(split_problems({rect(0, 0, 10, 10)}, {cw(rect(3, 3, 7, 7))}), "");
  std::size_t n = 0;
  const std::vector<Ring> pieces =
      detail::split_holes({rect(0, 0, 10, 10)}, {cw(rect(3, 3, 7, 7))}, n);
  EXPECT_EQ(n, 1u);
  EXPECT_GE(pieces.size(), 2u);  // one polygon cannot surround a hole
  Int128 sum = 0;
  for (const Ring& p : pieces) sum += twice_signed_area(p);
  EXPECT_EQ(sum, Int128(2 * (100 - 16)));
}

TEST(HoleSplitting, OneHoleIsCutAlongItsTwoBridges) {
  // The one-hole case is walked, not traced (checked builds trace it too and compare). Bridges:
  // from the hole's smallest vertex (3, 3) west, the ray meets x = 0 at (0, 3) and the triangle
  // (3, 3), (0, 3), (0, 0) holds no other vertex, so (0, 0); from its largest (7, 7) east, by the
  // same rule mirrored, (10, 10). The pieces lie on either side of the path they make.
  const Ring hole = cw(rect(3, 3, 7, 7));
  const std::set<Ring> want{
      detail::canonical_ring({{0, 0}, {10, 0}, {10, 10}, {7, 7}, {7, 3}, {3, 3}}),
      detail::canonical_ring({{10, 10}, {0, 10}, {0, 0}, {3, 3}, {3, 7}, {7, 7}})};
  for (std::ptrdiff_t start = 0; start < 4; ++start) {  // the outer ring from each corner
    Ring outer = rect(0, 0, 10, 10);
    std::rotate(outer.begin(), outer.begin() + start, outer.end());
    std::size_t n = 0;
    std::set<Ring> got;
    for (Ring& p : detail::split_holes({outer}, {hole}, n)) got.insert(detail::canonical_ring(p));
    EXPECT_EQ(got, want) << "outer ring from corner " << start;
    EXPECT_EQ(split_problems({outer}, {hole}), "");
  }
}

TEST(HoleSplitting, SeveralHolesSideBySideTouchingAndStacked) {
  // Two holes in a row, two holes touching at a corner, and a hole above and below another's
  // bridge.
  EXPECT_EQ(split_problems({rect(0, 0, 20, 10)}, {cw(rect(2, 3, 6, 7)), cw(rect(12, 3, 16, 7))}),
            "");
  EXPECT_EQ(split_problems({rect(0, 0, 20, 10)}, {cw(rect(2, 2, 6, 5)), cw(rect(6, 5, 10, 8))}),
            "");
  EXPECT_EQ(split_problems({rect(0, 0, 20, 12)},
                           {cw(rect(8, 5, 12, 7)), cw(rect(2, 1, 18, 3)), cw(rect(2, 9, 18, 11))}),
            "");
}

TEST(HoleSplitting, HoleTouchingTheOuterRingAtAVertex) {
  // The region of Assembly.HoleTouchingTheOuterRingIsSplitOffItsWalk: [0, 4]^2, with (0, 2) on
  // its left side, minus the triangle (0, 2), (2, 1), (2, 3): 16 - 2 = 14.
  const Ring outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 2}};
  const Ring hole = cw({{0, 2}, {2, 1}, {2, 3}});
  EXPECT_EQ(split_problems({outer}, {hole}), "");
  std::size_t n = 0;
  Int128 sum = 0;
  for (const Ring& p : detail::split_holes({outer}, {hole}, n)) sum += twice_signed_area(p);
  EXPECT_EQ(sum, Int128(28));
}

TEST(HoleSplitting, HolesGoToTheOuterRingAroundThem) {
  // Two outer rings of one region, each with a hole; an outer without holes stays as it is.
  const std::vector<Ring> outers{rect(0, 0, 10, 10), rect(20, 0, 30, 10), rect(40, 0, 45, 5)};
  const std::vector<Ring> holes{cw(rect(23, 3, 27, 7)), cw(rect(2, 2, 4, 4))};
  EXPECT_EQ(split_problems(outers, holes), "");
  std::size_t n = 0;
  const std::vector<Ring> pieces = detail::split_holes(outers, holes, n);
  EXPECT_NE(std::find(pieces.begin(), pieces.end(), rect(40, 0, 45, 5)), pieces.end());
}

}  // namespace
}  // namespace edgeland::test
