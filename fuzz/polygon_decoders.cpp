// The `polygon_pieces` target (decoders.hpp): valid polygons decoded from bytes, through
// triangulate(), convex_pieces() and centroid(), every promised property checked by
// tests/support/piece_checks (written apart from the kernel's algorithms).
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "decoders.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/centroid.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "piece_checks.hpp"
#include "piece_shapes.hpp"

namespace edgeland::fuzz {
namespace {

using Provider = FuzzedDataProvider;

constexpr std::size_t kMaxPolygons = 6;      // members of a decoded set that are checked
constexpr std::size_t kBruteForceUpTo = 64;  // vertices: diagonals by brute force, else xor
constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

// Draws in [lo, hi) for the test shape builders (piece_shapes.hpp).
struct ProviderDraw {
  Provider& in;
  std::int64_t operator()(std::int64_t lo, std::int64_t hi) {
    return in.ConsumeIntegralInRange<std::int64_t>(lo, hi - 1);
  }
};

// ---- decoding -------------------------------------------------------------------------------

// An integer map x -> M x + t with det M = +-1 or a scale, moving the shapes anywhere in range
// (near the bound too); orientation restored after a reflection. nullopt when out of range.
std::optional<Polygon> transformed(Provider& in, Polygon p) {
  static constexpr std::array<std::array<std::int64_t, 4>, 8> kMaps{{{1, 0, 0, 1},
                                                                     {0, -1, 1, 0},
                                                                     {-1, 0, 0, -1},
                                                                     {1, 1, 0, 1},
                                                                     {1, 0, -1, 1},
                                                                     {2, 1, 1, 1},
                                                                     {-1, 0, 0, 1},
                                                                     {0, 1, 1, 0}}};
  const auto m = in.PickValueInArray(kMaps);
  const std::int64_t scale = in.PickValueInArray<std::int64_t>({1, 1, 2, 3, 1000, 1 << 20});
  Int128 lo_x = kCoordBound, lo_y = kCoordBound, hi_x = -kCoordBound, hi_y = -kCoordBound;
  std::vector<std::array<Int128, 2>> image;
  for (const Point64& q : p) {
    const Int128 x = (Int128(m[0]) * q.x + Int128(m[1]) * q.y) * scale;
    const Int128 y = (Int128(m[2]) * q.x + Int128(m[3]) * q.y) * scale;
    image.push_back({x, y});
    lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y),
    hi_y = std::max(hi_y, y);
  }
  if (hi_x - lo_x > 2 * Int128(kCoordBound) || hi_y - lo_y > 2 * Int128(kCoordBound))
    return std::nullopt;
  // Where the box goes: at the lower or upper bound, or near the origin.
  const int place = in.ConsumeIntegralInRange(0, 2);
  const Int128 dx = place == 0 ? -kCoordBound - lo_x : place == 1 ? kCoordBound - hi_x : -lo_x;
  const Int128 dy = place == 0 ? -kCoordBound - lo_y : place == 1 ? kCoordBound - hi_y : -lo_y;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Int128 x = image[i][0] + dx, y = image[i][1] + dy;
    if (x < -kCoordBound || x > kCoordBound || y < -kCoordBound || y > kCoordBound)
      return std::nullopt;
    p[i] = {static_cast<std::int64_t>(x), static_cast<std::int64_t>(y)};
  }
  if (m[0] * m[3] - m[1] * m[2] < 0) std::reverse(p.begin(), p.end());
  return p;
}

// Rings on a small grid, normalized: valid polygons, with straight vertices where the clipper
// keeps them.
PolygonSet normalized_rings(Provider& in) {
  const std::int64_t grid = in.PickValueInArray<std::int64_t>({3, 8, 40});
  std::vector<Ring> rings(in.ConsumeIntegralInRange<std::size_t>(1, 3));
  for (Ring& r : rings) {
    r.resize(in.ConsumeIntegralInRange<std::size_t>(3, 16));
    for (Point64& q : r)
      q = {in.ConsumeIntegralInRange<std::int64_t>(0, grid),
           in.ConsumeIntegralInRange<std::int64_t>(0, grid)};
  }
  const FillRule rule = in.ConsumeBool() ? FillRule::kNonZero : FillRule::kEvenOdd;
  return normalize(rings, rule).polygons;
}

// A polyomino from a bit grid: every lattice point of its boundary a vertex.
PolygonSet polyomino(Provider& in) {
  const int side = in.ConsumeIntegralInRange(2, 10);
  std::set<testing::Cell> cells;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      if (in.ConsumeBool()) cells.insert({x, y});
  if (auto ring = testing::polyomino_boundary(cells)) return {*ring};
  return {};
}

// The shapes of the tests, sized by the input up to a few hundred vertices (the unit tests take
// them to 10^5): combs, spirals, zigzags, boxes with vertices on their sides.
PolygonSet parametric(Provider& in) {
  ProviderDraw draw{in};
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
      return {testing::unit_comb(in.ConsumeIntegralInRange<std::int64_t>(1, 64),
                                 in.ConsumeIntegralInRange<std::int64_t>(1, 20))};
    case 1:
      return {
          *testing::polyomino_boundary(testing::spiral_cells(in.ConsumeIntegralInRange(1, 24)))};
    case 2:
      return {testing::zigzag_band(in.ConsumeIntegralInRange<std::int64_t>(1, 64))};
    default: {
      const std::int64_t w = in.ConsumeIntegralInRange<std::int64_t>(2, 1000);
      const std::int64_t h = in.ConsumeIntegralInRange<std::int64_t>(2, 1000);
      return {testing::box_with_side_vertices(draw, w, h,
                                              in.ConsumeIntegralInRange<std::size_t>(0, 48))};
    }
  }
}

// ---- checks ---------------------------------------------------------------------------------

std::string described(const Polygon& p, std::size_t n) {
  return "\n  N = " + (n == kUnbounded ? std::string("unbounded") : std::to_string(n)) +
         "\n  polygon = " + to_wkt(p);
}

std::optional<Finding> found(const std::string& what, const Polygon& p, std::size_t n) {
  return Finding{what + described(p, n), ""};
}

std::optional<Finding> triangulation_checks(const Polygon& p, std::vector<Triangle>& triangles) {
  triangles = triangulate(p);
  std::string d = testing::triangulation_defect(p, triangles);
  if (d.empty())
    d = p.size() <= kBruteForceUpTo
            ? testing::diagonal_defect(p, triangles)
            : testing::union_defect(p, testing::triangle_polygons(p, triangles));
  if (!d.empty()) return found("triangulate: " + d, p, 0);
  return std::nullopt;
}

std::optional<Finding> valid_polygon_checks(const Polygon& p, std::size_t n) {
  std::vector<Triangle> triangles;
  if (auto f = triangulation_checks(p, triangles)) return f;
  const std::vector<Polygon> pieces = convex_pieces(p, n);
  std::string d = testing::convex_pieces_defect(p, pieces, n);
  if (d.empty()) d = testing::union_defect(p, pieces);
  if (!d.empty()) return found("convex_pieces: " + d, p, n);
  // One region, three descriptions: the centroids agree exactly (lowest terms).
  const RationalPoint c = centroid({p});
  if (!(centroid(testing::triangle_polygons(p, triangles)) == c) || !(centroid(pieces) == c))
    return found("centroid differs between the polygon, its triangles and its pieces", p, n);
  return std::nullopt;
}

// An invalid polygon: each algorithm throws InvalidInput with validate()'s first violation.
std::optional<Finding> invalid_polygon_checks(const Polygon& p, const Violation& expected) {
  const auto same = [&](const InvalidInput& e) {
    return e.operand == Operand::kPolygon && e.violation.rule == expected.rule &&
           e.violation.edge == expected.edge && e.violation.other_edge == expected.other_edge;
  };
  try {
    triangulate(p);
    return found("triangulate accepted an invalid polygon (" + expected.describe() + ")", p, 0);
  } catch (const InvalidInput& e) {
    if (!same(e)) return found(std::string("triangulate: another violation: ") + e.what(), p, 0);
  }
  try {
    convex_pieces(p);
    return found("convex_pieces accepted an invalid polygon (" + expected.describe() + ")", p, 8);
  } catch (const InvalidInput& e) {
    if (!same(e)) return found(std::string("convex_pieces: another violation: ") + e.what(), p, 8);
  }
  return std::nullopt;
}

std::optional<Finding> polygon_pieces_checks(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  const int mode = in.ConsumeIntegralInRange(0, 3);
  const std::size_t n =
      in.ConsumeBool() ? kUnbounded : in.ConsumeIntegralInRange<std::size_t>(3, 12);
  if (mode == 3) {  // a raw ring, valid or not
    Polygon raw(in.ConsumeIntegralInRange<std::size_t>(0, 12));
    for (Point64& q : raw)
      q = {in.ConsumeIntegralInRange<std::int64_t>(-4, 4),
           in.ConsumeIntegralInRange<std::int64_t>(-4, 4)};
    if (auto moved = transformed(in, raw)) raw = *moved;
    if (!raw.empty() && in.ConsumeIntegralInRange(0, 15) == 0)  // a coordinate beyond the bound
      raw[in.ConsumeIntegralInRange<std::size_t>(0, raw.size() - 1)].x = kCoordBound + 1;
    const ValidationReport report = validate(raw, 1);
    if (!report.ok()) return invalid_polygon_checks(raw, report.violations.front());
    return valid_polygon_checks(raw, n);
  }
  const PolygonSet set = mode == 0   ? normalized_rings(in)
                         : mode == 1 ? polyomino(in)
                                     : parametric(in);
  for (std::size_t i = 0; i < std::min(set.size(), kMaxPolygons); ++i) {
    const std::optional<Polygon> p = transformed(in, set[i]);
    if (!p) continue;
    if (!validate(*p, 1).ok()) return found("the decoder made an invalid polygon", *p, n);
    if (auto f = valid_polygon_checks(*p, n)) return f;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Finding> run_polygon_pieces(const std::uint8_t* data, std::size_t size) {
  try {
    return polygon_pieces_checks(data, size);
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what(), ""};
  }
}

}  // namespace edgeland::fuzz
