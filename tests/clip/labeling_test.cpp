// Labeling (clip/src/labeling.hpp): label_sides on real plane graphs against brute force. The
// state on the left of every half-edge must be what the snapped rings say about a point just
// left of the half-edge's first stretch (stage_inputs.hpp, SideProbe: an exact integer point in
// that face), computed with the kernel's winding_number on the rings snap rounding made of the
// input rings, without the graph:
//  * kWinding: the sum of all rings' winding numbers;
//  * kOwner: per channel, the polygon whose ring winds once round the point, or -1;
//  * kOwnerAndCount: channel 0 as kOwner, channel 1 the sum of its rings' winding numbers.
// check_single_cover on exact arrangements (nothing snapped) returns false exactly when some
// face is covered twice by one operand (overlapping members), true on valid operands.
#include "labeling.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "generators.hpp"
#include "stage_inputs.hpp"

namespace edgeland::test {
namespace {

using detail::LabelMode;
using detail::SideState;

// The point just left of half-edge h's first stretch (scaled, BruteStates::probe()).
Point64 left_of(const stages::BruteStates& brute, const detail::PlaneGraph& g, std::uint32_t h) {
  return brute.probe().left_of(g.vertices[g.origin(h)], g.first_step(h));
}

// What a state says about half-edge h, for comparisons that name the half-edge when they fail.
std::string said(const detail::PlaneGraph& g, std::uint32_t h, const SideState& s) {
  return stages::str_half_edge(g, h) + ": " + stages::str(s);
}

RC_GTEST_PROP(Labeling, WindingModeGivesTheWindingNumberLeftOfEveryHalfEdge, ()) {
  const stages::Arrangement a(*stages::crowded_rings(4, 20), *stages::crowded_rings(3, 20), false);
  RC_TAG(a.hot_pixels > 0 ? "snapped" : "exact");
  std::vector<SideState> left;
  RC_ASSERT(detail::label_sides(a.graph, LabelMode::kWinding, left));
  RC_ASSERT(left.size() == 2 * a.graph.edge_count());
  const stages::BruteStates brute(a);
  for (std::uint32_t h = 0; h < left.size(); ++h)
    RC_ASSERT(said(a.graph, h, left[h]) ==
              said(a.graph, h, brute.winding_state(left_of(brute, a.graph, h))));
}

// Valid operand pairs (generators.hpp: touching, nested, sharing edges, slivers, fans, ...).
rc::Gen<OperandPair> small_pair() {
  return rc::gen::exec([] {
    const std::int64_t r = *rc::gen::element<std::int64_t>(4, 8, 16, 30);
    return *gen::local_pair({*gen::coord(-2, 2), *gen::coord(-2, 2)}, r);
  });
}

RC_GTEST_PROP(Labeling, OwnerModesNameThePolygonCoveringEachSide, ()) {
  const OperandPair p = *small_pair();
  const stages::Arrangement a(p.a, p.b, true);
  RC_TAG(a.hot_pixels > 0 ? "snapped" : "exact");
  std::vector<SideState> owner, owner_and_count;
  RC_ASSERT(detail::label_sides(a.graph, LabelMode::kOwner, owner));
  RC_ASSERT(detail::label_sides(a.graph, LabelMode::kOwnerAndCount, owner_and_count));
  const stages::BruteStates brute(a);
  for (std::uint32_t h = 0; h < owner.size(); ++h) {
    const Point64 q = left_of(brute, a.graph, h);
    const std::optional<SideState> want = brute.owner_state(q);
    // Valid operands stay valid through snap rounding: one polygon per operand at most.
    if (!want)
      RC_FAIL("a snapped operand covers the left of " + stages::str_half_edge(a.graph, h) +
              " twice");
    RC_ASSERT(said(a.graph, h, owner[h]) == said(a.graph, h, *want));
    RC_ASSERT(owner_and_count[h].by_channel[0] == want->by_channel[0]);
    RC_ASSERT(owner_and_count[h].by_channel[1] == brute.cover(q, detail::kClipChannel));
  }
}

// Members of one operand that may overlap: axis-parallel rectangles (their contacts are all
// integer points) and triangles, counter-clockwise, in [0, 8]^2.
std::vector<Ring> maybe_overlapping(int max_members) {
  std::vector<Ring> out;
  const int n = stages::uniform_int(1, max_members);
  for (int k = 0; k < n; ++k) {
    if (stages::uniform(0, 3) != 0) {
      const std::int64_t x0 = *gen::coord(0, 7), y0 = *gen::coord(0, 7);
      const std::int64_t x1 = *gen::coord(x0 + 1, 8), y1 = *gen::coord(y0 + 1, 8);
      out.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    } else {
      out.push_back(gen::triangle_in({0, 0}, {8, 8}));
    }
  }
  return out;
}

RC_GTEST_PROP(Labeling, SingleCoverCheckFailsExactlyWhereAFaceIsCoveredTwice, ()) {
  const std::vector<Ring> subject = maybe_overlapping(4), clip = maybe_overlapping(3);
  const stages::Arrangement a(subject, clip, false);
  RC_PRE(a.hot_pixels == 0u);  // the check is exact only when nothing moved
  const stages::BruteStates brute(a);
  bool covered_twice = false;
  for (std::uint32_t h = 0; h < 2 * a.graph.edge_count(); ++h)
    covered_twice = covered_twice || brute.max_cover(left_of(brute, a.graph, h)) >= 2;
  RC_TAG(covered_twice ? "overlapping members" : "valid operands");
  std::vector<SideState> left;
  RC_ASSERT(detail::label_sides(a.graph, LabelMode::kOwner, left, true) == !covered_twice);
}

TEST(Labeling, NestedSquaresWindTwiceInside) {
  // [0, 10]^2 and [2, 8]^2, both counter-clockwise, in one channel: the ring between winds
  // once, the core twice, outside 0.
  const stages::Arrangement a(
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {8, 2}, {8, 8}, {2, 8}}}, {}, false);
  std::vector<SideState> left;
  ASSERT_TRUE(detail::label_sides(a.graph, LabelMode::kWinding, left));
  const auto& g = a.graph;
  for (std::uint32_t h = 0; h < left.size(); ++h) {
    const Point64 o = g.vertices[g.origin(h)], t = g.first_step(h);
    const bool inner = o.x >= 2 && o.x <= 8 && o.y >= 2 && o.y <= 8;
    // Counter-clockwise sides have the inside on their left: (t - o) turned left points in.
    const Point64 d{t.x - o.x, t.y - o.y};
    const Point64 mid2{o.x + t.x, o.y + t.y};  // twice the midpoint
    const Point64 towards_centre{10 - mid2.x, 10 - mid2.y};
    const bool inside_on_left = Int128(d.x) * towards_centre.y - Int128(d.y) * towards_centre.x > 0;
    const int want = inner ? (inside_on_left ? 2 : 1) : (inside_on_left ? 1 : 0);
    EXPECT_EQ(left[h].by_channel[0], want) << "half-edge " << h;
  }
  // As two members of one operand they overlap; in two operands they do not.
  EXPECT_FALSE(detail::label_sides(a.graph, LabelMode::kOwner, left, true));
  const stages::Arrangement b({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}},
                              {{{2, 2}, {8, 2}, {8, 8}, {2, 8}}}, false);
  EXPECT_TRUE(detail::label_sides(b.graph, LabelMode::kOwner, left, true));
}

TEST(Labeling, NeighboursSharingAnEdgePassTheSingleCoverCheck) {
  // Two squares of one operand side by side (their common edge x = 2 runs both ways) and a
  // triangle touching both at their common corner (2, 2): valid. The right square shifted one
  // unit left overlaps the left one.
  const Ring left_square{{0, 0}, {2, 0}, {2, 2}, {0, 2}},
      right_square{{2, 0}, {4, 0}, {4, 2}, {2, 2}}, above{{2, 2}, {3, 4}, {1, 4}};
  std::vector<SideState> left;
  const stages::Arrangement valid({left_square, right_square, above}, {}, false);
  ASSERT_TRUE(detail::label_sides(valid.graph, LabelMode::kOwner, left, true));
  // Across the common edge the owner changes straight from polygon 0 (west) to 1 (east).
  int seen = 0;
  for (std::uint32_t h = 0; h < left.size(); ++h) {
    const Point64 o = valid.graph.vertices[valid.graph.origin(h)], t = valid.graph.first_step(h);
    if (o.x != 2 || t.x != 2 || std::max(o.y, t.y) > 2) continue;
    ++seen;
    EXPECT_EQ(left[h].by_channel[0], t.y > o.y ? 0 : 1);  // going north, west is on the left
  }
  EXPECT_EQ(seen, 2);
  const stages::Arrangement overlapping({left_square, {{1, 0}, {3, 0}, {3, 2}, {1, 2}}}, {}, false);
  EXPECT_FALSE(detail::label_sides(overlapping.graph, LabelMode::kOwner, left, true));
}

}  // namespace
}  // namespace edgeland::test
