#include "edgeland/kernel/area.hpp"

#include <cstddef>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

}  // namespace

Int128 twice_signed_area(const Ring& ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 3) return 0;
  W sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i];
    const Point64 b = ring[i + 1 == n ? 0 : i + 1];
    sum = sum + formulas::cross<W>(a.x, a.y, b.x, b.y);
  }
  return sum.v;
}

Int128 twice_signed_area(const PolygonSet& set) noexcept {
  W sum = 0;
  for (const Polygon& p : set) sum = sum + W(twice_signed_area(p));
  return sum.v;
}

Orientation ring_orientation(const Ring& ring) noexcept {
  const Int128 a = twice_signed_area(ring);
  return static_cast<Orientation>((a > 0) - (a < 0));
}

}  // namespace edgeland
