// centroid(): the shoelace sums of the first moments and of the area, then one reduction to
// lowest terms (centroid.hpp).
#include "edgeland/kernel/centroid.hpp"

#include <utility>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

void require_centroid_input(const PolygonSet& set) {
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    vertices += set[i].size();
    for (std::size_t v = 0; v < set[i].size(); ++v)
      if (!in_range(set[i][v])) throw CoordinateOutOfRange(Operand::kPolygon, i, 0, v, set[i][v]);
  }
  if (static_cast<std::uint64_t>(vertices) > kMaxCentroidVertices)
    throw TooManyVertices(static_cast<std::size_t>(kMaxCentroidVertices), vertices);
}

// Six times the first moments about both axes, summed over every edge of every ring of at least
// 3 vertices: |term| <= 4 B^3, so at most kMaxCentroidVertices terms fit (proofs/).
struct Moments {
  W x = 0, y = 0;
};

Moments moments(const PolygonSet& set) {
  Moments m;
  for (const Polygon& ring : set) {
    if (ring.size() < 3) continue;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point64 a = ring[i], b = ring[i + 1 == ring.size() ? 0 : i + 1];
      m.x = m.x + formulas::moment_term<W>(a.x, b.x, a.x, a.y, b.x, b.y);
      m.y = m.y + formulas::moment_term<W>(a.y, b.y, a.x, a.y, b.x, b.y);
    }
  }
  return m;
}

UInt128 gcd(UInt128 a, UInt128 b) {
  while (b != 0) a = std::exchange(b, a % b);
  return a;
}

// Divides all three by their greatest common divisor (den > 0, so it is positive); dividing
// cannot overflow.
RationalPoint lowest_terms(Int128 x_num, Int128 y_num, Int128 den) {
  const auto g =
      static_cast<Int128>(gcd(gcd(unsigned_abs(x_num), unsigned_abs(y_num)), unsigned_abs(den)));
  return {x_num / g, y_num / g, den / g};
}

}  // namespace

RationalPoint centroid(const PolygonSet& set) {
  require_centroid_input(set);
  const Int128 twice_area = twice_signed_area(set);
  if (twice_area <= 0) throw NonPositiveArea(twice_area);
  const Moments m = moments(set);
  return lowest_terms(m.x.v, m.y.v, formulas::centroid_denominator<W>(twice_area).v);
}

}  // namespace edgeland
