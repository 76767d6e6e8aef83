#include "edgeland/kernel/perimeter.hpp"

#include <cstddef>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

}  // namespace

UInt128 isqrt(UInt128 n) noexcept {
  using U = UInt128;
  // Builds the root one bit at a time from the top. `bit` walks the powers of four; the
  // invariant is root^2 + remaining == n, with root scaled by the bits still to come.
  // root + bit never overflows: root < 2^64 and bit <= 2^126.
  U root = 0;
  U bit = U(1) << 126;
  while (bit > n) bit >>= 2;
  while (bit != 0) {
    if (n >= root + bit) {
      n -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return root;
}

PerimeterBounds perimeter_bounds(const Ring& ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 2) return {};
  W lo = 0, hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i];
    const Point64 b = ring[i + 1 == n ? 0 : i + 1];
    // |b - a|^2 as the dot product of b - a with itself.
    const Int128 squared = formulas::dot_from<W>(a.x, a.y, b.x, b.y, b.x, b.y).v;
    const auto root = static_cast<Int128>(isqrt(static_cast<UInt128>(squared)));
    lo = lo + W(root);
    hi = hi + W(root * root == squared ? root : root + 1);
  }
  return {lo.v, hi.v};
}

PerimeterBounds perimeter_bounds(const PolygonSet& set) noexcept {
  W lo = 0, hi = 0;
  for (const Polygon& p : set) {
    const PerimeterBounds b = perimeter_bounds(p);
    lo = lo + W(b.lo);
    hi = hi + W(b.hi);
  }
  return {lo.v, hi.v};
}

}  // namespace edgeland
