#include "edgeland/kernel/fraction.hpp"

#include <cstdint>

namespace edgeland {

UInt256 multiply_wide(UInt128 a, UInt128 b) noexcept {
  using U = UInt128;
  // Schoolbook on 64-bit limbs: each partial product fits 128 bits, and the middle column
  // (at most three values below 2^64) fits as well, so no carry is lost.
  const U a0 = static_cast<std::uint64_t>(a), a1 = a >> 64;
  const U b0 = static_cast<std::uint64_t>(b), b1 = b >> 64;
  const U p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const U mid = (p00 >> 64) + static_cast<std::uint64_t>(p01) + static_cast<std::uint64_t>(p10);
  UInt256 r;
  r.lo = (mid << 64) | static_cast<std::uint64_t>(p00);
  r.hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
  return r;
}

int compare(const Fraction& a, const Fraction& b) noexcept {
  const int sa = (a.num > 0) - (a.num < 0);
  const int sb = (b.num > 0) - (b.num < 0);
  if (sa != sb) return sa < sb ? -1 : 1;
  if (sa == 0) return 0;
  // Same sign: compare |a.num| * b.den with |b.num| * a.den, flipped for negative values.
  const UInt256 lhs = multiply_wide(unsigned_abs(a.num), static_cast<UInt128>(b.den));
  const UInt256 rhs = multiply_wide(unsigned_abs(b.num), static_cast<UInt128>(a.den));
  const int magnitude = lhs < rhs ? -1 : (rhs < lhs ? 1 : 0);
  return sa > 0 ? magnitude : -magnitude;
}

}  // namespace edgeland
