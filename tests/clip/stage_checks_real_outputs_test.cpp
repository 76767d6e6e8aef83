// The stage checkers (clip/src/stage_checks.hpp) accept what the real stages produce: fixed
// inputs that reach every kind of output (cut and chained segments, snapped crossings, shared
// edges, holes, nested components, winding numbers, merged collinear stacks, the overlay's
// owner-and-count labels), random operand pairs and crowded self-crossing rings, and an input
// of 10^5 segments (a quadratic checker would not finish it). A failure here is either a
// checker that is too strict or a stage that breaks its promise: read the message.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"  // before generators.hpp, which uses bounding_box
#include "generators.hpp"
#include "stage_checks.hpp"
#include "stage_outputs.hpp"

namespace edgeland::detail {
namespace {

Polygon box(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

void check_all(const StageOutputs& s) {
  check_fragments(s.edges, s.fragments, s.touched);
  check_plane_graph(s.graph);
  check_labels(s.graph, s.mode, s.left);
  check_assembled(s.assembled);
}

constexpr ClipOp kOps[] = {ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference,
                           ClipOp::kXor};

bool has_chain(const PlaneGraph& g) {
  for (const PlaneGraph::Chain& c : g.chain)
    if (c.count > 0) return true;
  return false;
}

TEST(StageCheckRealOutputs, OverlappingSquaresEveryOperation) {
  for (ClipOp op : kOps) {
    const auto s =
        clip_stages({box(0, 0, 10, 10), box(100, 100, 110, 110)}, {box(5, 5, 15, 15)}, op);
    EXPECT_FALSE(s->fragments.empty());
    EXPECT_TRUE(has_chain(s->graph));
    EXPECT_NO_THROW(check_all(*s)) << op_name(op);
  }
}

TEST(StageCheckRealOutputs, SnappedCrossings) {
  for (ClipOp op : kOps) {
    const auto s = clip_stages({{{0, 0}, {7, 1}, {2, 6}}}, {{{1, -1}, {6, 5}, {-1, 3}}}, op);
    EXPECT_GT(s->hot_pixels, 0u);
    EXPECT_NO_THROW(check_all(*s)) << op_name(op);
  }
}

TEST(StageCheckRealOutputs, SharedEdgesAndVertices) {
  for (ClipOp op : kOps) {
    const auto s = clip_stages({box(0, 0, 10, 10), box(20, 10, 30, 20)},
                               {box(10, 0, 20, 10), box(10, 10, 20, 15)}, op);
    EXPECT_NO_THROW(check_all(*s)) << op_name(op);
  }
}

TEST(StageCheckRealOutputs, HolesAndNestedComponents) {
  for (ClipOp op : kOps) {
    const auto s = clip_stages({box(0, 0, 10, 10), box(20, 0, 30, 10), box(40, 0, 50, 10)},
                               {box(3, 3, 6, 6), box(23, 3, 26, 6), box(-5, 20, 60, 30)}, op);
    if (op == ClipOp::kDifference) {
      EXPECT_EQ(s->assembled.holed.size(), 2u);
    }
    EXPECT_NO_THROW(check_all(*s)) << op_name(op);
  }
}

TEST(StageCheckRealOutputs, WindingNumbersOfSelfCrossingRings) {
  const std::vector<Ring> rings{{{0, 0}, {10, 10}, {10, 0}, {0, 10}},  // bow tie
                                box(2, 2, 8, 8),
                                box(3, 3, 7, 7),                   // winding 2 and 3
                                {{4, 4}, {4, 6}, {6, 6}, {6, 4}},  // clockwise: back to 2
                                {{0, 0}, {20, 1}, {5, 5}, {20, 9}, {0, 10}, {3, 5}}};
  for (FillRule rule :
       {FillRule::kEvenOdd, FillRule::kNonZero, FillRule::kPositive, FillRule::kNegative}) {
    const auto s = normalize_stages(rings, rule);
    EXPECT_NO_THROW(check_all(*s)) << fill_rule_name(rule);
  }
}

TEST(StageCheckRealOutputs, MergedCollinearStacks) {
  std::vector<Ring> rings;
  for (std::int64_t k = 0; k < 12; ++k) rings.push_back(box(3 * k, 0, 3 * k + 20, 10 + k % 3));
  const auto s = normalize_stages(rings, FillRule::kNonZero, 0);
  EXPECT_TRUE(s->merged);
  EXPECT_NO_THROW(check_all(*s));
}

TEST(StageCheckRealOutputs, OverlayOwnerAndCountLabels) {
  // Regions (channel 0, owners) and a shape with a window ring (channel 1, a count), as relabel.
  auto s = std::make_unique<StageOutputs>();
  append_ring_edges({box(0, 0, 10, 10), box(10, 0, 20, 10)}, 0, true, s->edges);
  append_ring_edges({{{5, -5}, {25, 5}, {5, 15}}, box(-1, -1, 16, 11)}, 1, true, s->edges);
  const std::vector<std::uint32_t> region_labels{1, 2}, table{0, 3, 3};
  const RelabelTable relabel{region_labels.data(), table.data(), table.size(), 2};
  later_stages(*s, LabelMode::kOwnerAndCount, LabelOf::relabel(relabel), true);
  EXPECT_NO_THROW(check_all(*s));
}

// A zigzag strip of `teeth` teeth, counter-clockwise; `rise` sets the slope of its teeth.
Ring zigzag(std::int64_t teeth, std::int64_t dx, std::int64_t dy, std::int64_t rise) {
  Ring r{{dx, dy - 50}, {4 * teeth + dx, dy - 50}};
  for (std::int64_t i = teeth; i-- > 0;) {
    r.push_back({4 * i + 4 + dx, dy});
    r.push_back({4 * i + 2 + dx, dy + rise});
  }
  r.push_back({dx, dy});
  return r;
}

TEST(StageCheckRealOutputs, HundredThousandSegmentsInLinearishTime) {
  // Two zigzags crossing tooth by tooth at non-integer points: 10^5 segments, 10^5 crossings.
  const auto s = clip_stages({zigzag(25'000, 0, 0, 3)}, {zigzag(25'000, 1, 1, 5)}, ClipOp::kUnion);
  EXPECT_GE(s->edges.size(), 100'000u);
  EXPECT_GT(s->hot_pixels, 10'000u);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NO_THROW(check_all(*s));
  const auto seconds =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start);
  EXPECT_LT(seconds.count(), 20);  // a pairwise check would take hours
}

RC_GTEST_PROP(StageCheckRealOutputs, RandomOperandPairs, ()) {
  const test::OperandPair pair = *test::gen::operand_pair();
  for (ClipOp op : kOps) {
    const auto s = clip_stages(pair.a, pair.b, op);
    check_all(*s);
  }
}

// Rings of random points (crossing themselves and each other) in a small square, under every
// fill rule; half of the time every stack of collinear edges is merged first.
RC_GTEST_PROP(StageCheckRealOutputs, CrowdedRingsUnderWinding, ()) {
  const std::int64_t side = *rc::gen::element<std::int64_t>(6, 12, 40, 1000);
  std::vector<Ring> rings(static_cast<std::size_t>(*rc::gen::inRange(1, 5)));
  for (Ring& r : rings) {
    const int n = *rc::gen::inRange(3, 25);
    for (int i = 0; i < n; ++i)
      r.push_back({*rc::gen::inRange<std::int64_t>(0, side + 1),
                   *rc::gen::inRange<std::int64_t>(0, side + 1)});
  }
  const std::size_t budget =
      *rc::gen::arbitrary<bool>() ? 0 : std::numeric_limits<std::size_t>::max();
  const FillRule rule =
      *rc::gen::element(FillRule::kEvenOdd, FillRule::kNonZero, FillRule::kPositive);
  check_all(*normalize_stages(rings, rule, budget));
}

}  // namespace
}  // namespace edgeland::detail
