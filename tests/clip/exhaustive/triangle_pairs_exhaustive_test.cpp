// Bounded-exhaustive checks (issue 4, "Verification"): every pair of triangles with vertices on
// a 4 x 4 grid, and every triangle on an 8 x 8 grid against a unit square, under all four
// operations in both orders, compared with the exact result (two_polygon_reference.hpp):
//   * the output is valid (checked mode, and validate() here);
//   * where nothing was snapped, its area is exactly the exact area and every half-integer
//     point of the surrounding box is in its closure iff in the exact closure;
//   * otherwise the accuracy contract: area within the perimeter bound, every vertex within
//     one unit of the boundary of the exact pieces, every half-integer point farther than 1.5
//     from the exact boundary classified as in the exact result;
//   * on a sample of cases (one in 499) the full CGAL oracle as well, which also checks this
//     file's integer reference against CGAL's exact area.
// Each test prints its case count.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "polygon_set_helpers.hpp"
#include "two_polygon_reference.hpp"

namespace edgeland::test {
namespace {

// Every non-degenerate triangle with vertices in [0, n)^2, once per vertex set, CCW.
std::vector<Polygon> triangles_on_grid(int n) {
  std::vector<Point64> pts;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) pts.push_back({x, y});
  std::vector<Polygon> out;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j)
      for (std::size_t k = j + 1; k < pts.size(); ++k) {
        const Point64 a = pts[i], b = pts[j], c = pts[k];
        const Int128 cr = Int128(b.x - a.x) * (c.y - a.y) - Int128(b.y - a.y) * (c.x - a.x);
        if (cr > 0) out.push_back({a, b, c});
        if (cr < 0) out.push_back({a, c, b});
      }
  return out;
}

struct Tally {
  std::size_t cases = 0, snapped = 0, cgal_checked = 0, points = 0, failures = 0;
  std::vector<std::string> messages;  // the first few failures

  void fail(const std::string& what, ClipOp op, const Polygon& a, const Polygon& b) {
    ++failures;
    if (messages.size() < 12)
      messages.push_back(what + "\n  " + op_name(op) + "\n  A = " + to_wkt(a) +
                         "\n  B = " + to_wkt(b));
  }
  void report(const char* name, double seconds) const {
    std::cout << "[exhaustive] " << name << ": " << cases << " cases (" << snapped << " snapped), "
              << points << " point classifications, " << cgal_checked << " also checked with CGAL, "
              << failures << " failures, " << seconds << " s\n";
    for (const std::string& m : messages) std::cout << "  FAIL " << m << "\n";
  }
};

void check_case(ClipOp op, const Polygon& a, const Polygon& b, const TwoPolygonReference& ref,
                bool with_cgal, Tally& t) {
  ++t.cases;
  const Outcome o = run_clip(op, PolygonSet{a}, PolygonSet{b});
  if (!o.ok()) return t.fail(o.error, op, a, b);
  const PolygonSet& s = o.result->polygons;
  const ValidationReport v = validate(s);
  if (!v.ok())
    return t.fail("invalid output " + to_wkt(s) + ": " + v.violations.front().describe(), op, a, b);
  const bool snapped = o.result->stats.vertices_snapped != 0;
  if (snapped) ++t.snapped;
  const Int128 S = ref.scale();
  const Int128 exact2 = ref.twice_area_scaled(op);
  const Int128 got2 = twice_area(s) * S * S;
  const Int128 err = got2 > exact2 ? got2 - exact2 : exact2 - got2;
  if (!snapped && err != 0)
    return t.fail("unsnapped output " + to_wkt(s) + " has the wrong area", op, a, b);
  if (err > 2 * S * S * ref.perimeter_ceil(op))
    return t.fail("area of " + to_wkt(s) + " beyond the perimeter bound", op, a, b);
  for (const Polygon& poly : s)
    for (const Point64& vtx : poly)
      if (!ref.near_boundary(op, ref.scaled(vtx), S * S, true))
        return t.fail("vertex (" + std::to_string(vtx.x) + ' ' + std::to_string(vtx.y) + ") of " +
                          to_wkt(s) + " farther than 1 from the exact boundary",
                      op, a, b);
  // Half-integer points of the box around both operands, one unit of margin.
  std::int64_t x0 = a[0].x, x1 = a[0].x, y0 = a[0].y, y1 = a[0].y;
  for (const Polygon* p : {&a, &b})
    for (const Point64& q : *p) {
      x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
      y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    }
  for (std::int64_t X = 2 * x0 - 2; X <= 2 * x1 + 2; ++X)
    for (std::int64_t Y = 2 * y0 - 2; Y <= 2 * y1 + 2; ++Y) {
      const Scaled p{Int128(X) * (S / 2), Int128(Y) * (S / 2)};
      if (snapped && ref.near_boundary(op, p, 9 * (S / 2) * (S / 2), false)) continue;
      ++t.points;
      const bool in_exact = ref.in_closure(op, p);
      const bool in_out = locate(s, SamplePoint{X, Y, 2}) != Where::kOutside;
      if (in_exact != in_out)
        return t.fail("point (" + std::to_string(X) + "/2 " + std::to_string(Y) + "/2) is " +
                          (in_out ? "in" : "not in") + " the output " + to_wkt(s) + " but " +
                          (in_exact ? "in" : "not in") + " the exact result",
                      op, a, b);
    }
  if (with_cgal) {
    ++t.cgal_checked;
    const ExactCase exact = exact_clip(op, {a}, {b});
    const Rational ref_area =
        Rational(BigInt(to_string(exact2))) / Rational(BigInt(to_string(2 * S * S)));
    if (exact.result.area() != ref_area)
      return t.fail("the integer reference's area " + ref_area.str() + " differs from CGAL's " +
                        exact.result.area().str(),
                    op, a, b);
    const ContractReport r = check_clip(op, {a}, {b}, *o.result);
    if (!r.ok()) return t.fail(r.failure, op, a, b);
  }
}

constexpr ClipOp kOps[] = {ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference,
                           ClipOp::kXor};

TEST(ClipExhaustive, EveryPairOfTrianglesOnA4x4GridUnderAllOperations) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Polygon> tris = triangles_on_grid(4);
  ASSERT_EQ(tris.size(), 516u);  // C(16,3) = 560 minus 44 collinear triples
  Tally t;
  std::size_t pair = 0;
  for (const Polygon& a : tris)
    for (const Polygon& b : tris) {
      const TwoPolygonReference ref(a, b);
      for (ClipOp op : kOps) check_case(op, a, b, ref, pair % 499 == 0, t);
      ++pair;
    }
  t.report("triangle pairs on a 4x4 grid",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  EXPECT_EQ(t.cases, 516u * 516u * 4u);
  EXPECT_EQ(t.failures, 0u);
}

TEST(ClipExhaustive, EveryTriangleOnAn8x8GridAgainstAUnitSquare) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Polygon> tris = triangles_on_grid(8);
  const Polygon square{{3, 3}, {4, 3}, {4, 4}, {3, 4}};
  Tally t;
  std::size_t pair = 0;
  for (const Polygon& tri : tris) {
    const TwoPolygonReference tri_first(tri, square), square_first(square, tri);
    for (ClipOp op : kOps) {
      check_case(op, tri, square, tri_first, pair % 499 == 0, t);
      check_case(op, square, tri, square_first, pair % 499 == 1, t);
    }
    ++pair;
  }
  t.report("triangles on an 8x8 grid against a unit square",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  EXPECT_EQ(t.cases, tris.size() * 8);
  EXPECT_EQ(t.failures, 0u);
}

}  // namespace
}  // namespace edgeland::test
