// The working memory clip.hpp promises (MEMORY): the peak of heap bytes allocated during one
// operation, beyond what was allocated before it, stays within a bound per input edge plus a
// bound per crossing. Measured by replacing the global allocation functions
// (tests/support/allocation_meter.hpp, as the load memory test does).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "allocation_meter.hpp"
#include "edgeland/clip/clip.hpp"

namespace edgeland {
namespace {

// Bytes the operation needed on top of its inputs (the result included).
template <class F>
std::size_t peak_during(F&& operation) {
  return fuzz::peak_heap_during(operation);
}

// n vertices round (cx, cy), radii alternating r and inner * r (a circle when inner is 1, a
// zigzag star below), the angles turned by `turn`: integer coordinates, rounded (the test's own
// input, not library arithmetic).
Polygon ring_of(std::size_t n, std::int64_t cx, std::int64_t cy, double r, double inner,
                double turn) {
  Polygon p;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n) + turn;
    const double radius = i % 2 == 0 ? r : inner * r;
    p.push_back({cx + std::llround(radius * std::cos(a)), cy + std::llround(radius * std::sin(a))});
  }
  return p;
}

// The bounds stated in clip.hpp (MEMORY).
constexpr std::size_t kBytesPerEdge = 120, kBytesPerCrossing = 2000, kSlack = 1 << 20;

TEST(ClipMemory, SmoothInputsStayWithinTheBytesPerEdge) {
  // Two circles of 2 * 10^5 vertices, one moved off the other: 4 * 10^5 edges, 2 crossings.
  const ValidSet a(PolygonSet{ring_of(200000, 0, 0, 1e8, 1, 0)}, Operand::kSubject);
  const ValidSet b(PolygonSet{ring_of(200000, 50000000, 0, 1e8, 1, 0)}, Operand::kClip);
  ClipStats stats;
  const std::size_t peak = peak_during([&] { stats = clip(ClipOp::kDifference, a, b).stats; });
  const std::size_t edges = 400000;
  RecordProperty("bytes_per_edge", static_cast<int>(peak / edges));
  EXPECT_LE(stats.intersections, 8u);
  EXPECT_LE(peak, kBytesPerEdge * edges + kSlack) << peak / edges << " bytes per edge";
}

TEST(ClipMemory, CrossingsStayWithinTheBytesPerCrossing) {
  // Two zigzag stars, one turned by a few millionths of a turn: every edge crosses one of the
  // other's, and every crossing is rounded.
  const ValidSet a(PolygonSet{ring_of(100000, 0, 0, 1e8, 0.9, 0)}, Operand::kSubject);
  const ValidSet b(PolygonSet{ring_of(100000, 1234, -777, 1e8, 0.9, 2 * std::numbers::pi * 3e-6)},
                   Operand::kClip);
  ClipStats stats;
  const std::size_t peak = peak_during([&] { stats = clip(ClipOp::kDifference, a, b).stats; });
  const std::size_t edges = 200000;
  ASSERT_GE(stats.intersections, 50000u);
  RecordProperty(
      "bytes_per_crossing",
      static_cast<int>((peak - std::min(peak, kBytesPerEdge * edges)) / stats.intersections));
  EXPECT_LE(peak, kBytesPerEdge * edges + kBytesPerCrossing * stats.intersections + kSlack)
      << peak << " bytes for " << edges << " edges and " << stats.intersections << " crossings";
}

}  // namespace
}  // namespace edgeland
