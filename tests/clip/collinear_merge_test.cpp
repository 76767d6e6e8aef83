// Stacks of collinear, overlapping edges under a winding fill (issue 16, point 2): normalize
// merges them into weighted stretches (clip/src/collinear_merge.hpp) instead of noding every
// overlapping pair. Before that, 4,000 squares shifted along a common side took 444 s and 5.7 GB
// and 10^5 identical squares hours; the first two tests below ran into clip_tests' time-out.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <numeric>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "generators.hpp"
#include "pipeline.hpp"
#include "winding_reference.hpp"

namespace edgeland::test {
namespace {

Ring rectangle(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

ClipResult normalized(const std::vector<Ring>& rings, FillRule rule) {
  const Outcome o = run_normalize(rings, rule);
  EXPECT_TRUE(o.ok()) << o.error.substr(0, 300);
  return o.ok() ? *o.result : ClipResult{};
}

TEST(CollinearStacks, IdenticalSquaresFillByTheirCount) {
  const Ring square = rectangle(0, 0, 10, 10);
  const std::vector<Ring> even(100000, square);
  EXPECT_EQ(normalized(even, FillRule::kNonZero).polygons, PolygonSet{square});
  EXPECT_EQ(normalized(even, FillRule::kPositive).polygons, PolygonSet{square});
  EXPECT_TRUE(normalized(even, FillRule::kEvenOdd).polygons.empty());  // 10^5 copies: even
  EXPECT_TRUE(normalized(even, FillRule::kNegative).polygons.empty());
  std::vector<Ring> odd = even;
  odd.push_back(square);
  EXPECT_EQ(normalized(odd, FillRule::kEvenOdd).polygons, PolygonSet{square});
  // Reversed copies cancel their twins: 50,001 forwards and 50,000 backwards wind once.
  for (std::size_t i = 0; i < 50000; ++i) std::reverse(odd[i].begin(), odd[i].end());
  EXPECT_EQ(normalized(odd, FillRule::kPositive).polygons, PolygonSet{square});
}

// Square i spans [i, i + 10^5] x [0, 10]: the winding number over [k, k + 1) x (0, 10) is k + 1
// for k < 4,000, then 4,000, then 3,999 - j over [10^5 + j, 10^5 + j + 1).
TEST(CollinearStacks, ShiftedSquaresFillByTheirCount) {
  constexpr std::int64_t kCount = 4000, kWidth = 100000;
  std::vector<Ring> rings;
  for (std::int64_t i = 0; i < kCount; ++i) rings.push_back(rectangle(i, 0, i + kWidth, 10));
  EXPECT_EQ(normalized(rings, FillRule::kNonZero).polygons,
            PolygonSet{rectangle(0, 0, kCount - 1 + kWidth, 10)});
  // Odd counts: k + 1 for even k < 4,000 (2,000 unit strips), 3,999 - j for even j (2,000).
  const ClipResult odd = normalized(rings, FillRule::kEvenOdd);
  EXPECT_TRUE(validate(odd.polygons, 1).ok());
  EXPECT_EQ(twice_signed_area(odd.polygons), Int128(2 * 4000 * 10));
  EXPECT_EQ(odd.polygons.size(), 4000u);
}

// A few rings and copies of them: identical, reversed, and shifted along one of their edges
// (that edge's copy then overlaps it on its line), in every mix.
rc::Gen<std::vector<Ring>> stacked_rings() {
  return rc::gen::exec([] {
    const std::int64_t r = *rc::gen::elementOf(std::vector<std::int64_t>{4, 12, 1000});
    std::vector<Ring> rings;
    const int bases = *rc::gen::inRange(1, 3);
    for (int b = 0; b < bases; ++b) {
      Ring base = *gen::shape({0, 0}, r);
      rings.push_back(base);
      const int copies = *rc::gen::inRange(1, 6);
      for (int c = 0; c < copies; ++c) {
        Ring copy = base;
        const std::size_t e =
            static_cast<std::size_t>(*gen::coord(0, std::int64_t(base.size()) - 1));
        const Point64 a = base[e], z = base[(e + 1) % base.size()];
        const std::int64_t g = std::gcd(z.x - a.x, z.y - a.y);
        const std::int64_t k = *gen::coord(-2, 2);  // steps of the edge's smallest lattice vector
        for (Point64& p : copy) p = {p.x + k * (z.x - a.x) / g, p.y + k * (z.y - a.y) / g};
        if (*rc::gen::arbitrary<bool>()) std::reverse(copy.begin(), copy.end());
        rings.push_back(copy);
      }
    }
    return rings;
  });
}

// The merged path through the pipeline itself (every stack merged, whatever its size).
ClipResult run_merging_every_stack(const std::vector<Ring>& rings, FillRule rule) {
  detail::Pipeline p;
  detail::append_ring_edges(rings, 0, false, p.edges);
  p.simple_rings = false;
  p.mode = detail::LabelMode::kWinding;
  p.label_of = detail::LabelOf::fill(rule);
  p.overlap_budget = 0;
  return detail::run(p).clipped;
}

RC_GTEST_PROP(CollinearStacks, MergedStacksMeetTheContractOfTheExactFill, ()) {
  const std::vector<Ring> rings = *stacked_rings();
  const FillRule rule = *rc::gen::element(FillRule::kEvenOdd, FillRule::kNonZero,
                                          FillRule::kPositive, FillRule::kNegative);
  const std::string described = std::string("normalize ") + fill_rule_name(rule) +
                                " rings = " + to_wkt(PolygonSet(rings.begin(), rings.end()));
  const ClipResult merged = run_merging_every_stack(rings, rule);
  const ValidationReport report = validate(merged.polygons, 1);
  if (!report.ok())
    RC_FAIL("invalid: " + report.violations.front().describe() + "\n  " + described);
  const FilledRegion exact = filled_region(rings, rule);
  RC_ASSERT(exact.region.area() == exact.trapezoid_area);
  std::vector<Point64> inputs;
  for (const Ring& ring : rings) inputs.insert(inputs.end(), ring.begin(), ring.end());
  const ContractReport rep = check_contract(exact_region(exact.region), merged, inputs, described);
  if (!rep.ok()) RC_FAIL(rep.failure);
  // Where nothing is rounded the arrangement is the one noding builds pair by pair, so the
  // polygons are the same.
  const Outcome plain = run_normalize(rings, rule);
  if (!plain.ok()) RC_FAIL(plain.error);
  if (merged.stats.vertices_snapped == 0 && plain.result->stats.vertices_snapped == 0)
    RC_ASSERT(merged.polygons == plain.result->polygons);
}

}  // namespace
}  // namespace edgeland::test
