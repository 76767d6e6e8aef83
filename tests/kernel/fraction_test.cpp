// fraction.hpp: exact comparison of Int128 fractions through 256-bit products.
#include "edgeland/kernel/fraction.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <limits>

#include "exact_reference.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

constexpr Int128 kMax = std::numeric_limits<Int128>::max();
constexpr Int128 kMin = std::numeric_limits<Int128>::min();

cpp_rational value(const Fraction& f) { return cpp_rational(big(f.num), big(f.den)); }

int ref_compare(const Fraction& a, const Fraction& b) {
  const cpp_rational d = value(a) - value(b);
  return d.sign();
}

TEST(FractionCompare, ProductsBeyondInt128AreExact) {
  // (2^127 - 1) / (2^127 - 2) > 1 > (2^127 - 2) / (2^127 - 1): cross-multiplying needs 254 bits.
  EXPECT_EQ(compare({kMax, kMax - 1}, {kMax - 1, kMax}), 1);
  EXPECT_EQ(compare({kMax - 1, kMax}, {kMax, kMax - 1}), -1);
  EXPECT_EQ(compare({kMin, kMax}, {kMin + 1, kMax}), -1);
  EXPECT_EQ(compare({kMin, 1}, {kMax, 1}), -1);
}

TEST(FractionCompare, EqualValuesWithDifferentTermsCompareEqual) {
  EXPECT_EQ(compare({1, 2}, {2, 4}), 0);
  EXPECT_EQ(compare({-3, 9}, {-1, 3}), 0);
  EXPECT_EQ(compare({0, 5}, {0, kMax}), 0);
  EXPECT_EQ(compare({kMax, kMax}, {1, 1}), 0);
}

TEST(FractionCompare, SignsDecideFirst) {
  EXPECT_EQ(compare({-1, kMax}, {0, 1}), -1);
  EXPECT_EQ(compare({1, kMax}, {-kMax, 1}), 1);
}

TEST(MultiplyWide, LargestOperands) {
  using U = unsigned __int128;
  const U max = ~U(0);
  // (2^128 - 1)^2 = 2^256 - 2^129 + 1.
  const UInt256 p = multiply_wide(max, max);
  EXPECT_EQ(p.lo, U(1));
  EXPECT_EQ(p.hi, max - 1);
}

Int128 gen_int128() {
  // Mix magnitudes: tiny, around 2^64, full width and the extremes.
  const auto hi = *rc::gen::arbitrary<std::uint64_t>();
  const auto lo = *rc::gen::arbitrary<std::uint64_t>();
  switch (*rc::gen::inRange(0, 4)) {
    case 0:
      return *rc::gen::inRange<std::int64_t>(-8, 9);
    case 1:
      return static_cast<Int128>(static_cast<std::int64_t>(lo));
    case 2:
      return *rc::gen::element(kMax, kMin, kMax - 1, kMin + 1);
    default:
      return static_cast<Int128>((static_cast<unsigned __int128>(hi) << 64) | lo);
  }
}

Fraction gen_fraction() {
  Int128 den = gen_int128();
  if (den < 0) den = den == kMin ? kMax : -den;
  if (den == 0) den = 1;
  return {gen_int128(), den};
}

RC_GTEST_PROP(FractionCompareProperty, MatchesCppRational, ()) {
  const Fraction a = gen_fraction();
  // Often a value equal to a with other terms, to exercise the equality case.
  Fraction b = gen_fraction();
  if (*rc::gen::inRange(0, 4) == 0 && a.num >= -(Int128(1) << 60) && a.num <= Int128(1) << 60 &&
      a.den <= Int128(1) << 60) {
    const Int128 k = *rc::gen::inRange<std::int64_t>(1, 1 << 20);
    b = {a.num * k, a.den * k};
  }
  RC_ASSERT(compare(a, b) == ref_compare(a, b));
  RC_ASSERT(compare(b, a) == -ref_compare(a, b));
}

RC_GTEST_PROP(MultiplyWideProperty, MatchesCppInt, ()) {
  const auto a = static_cast<unsigned __int128>(gen_int128());
  const auto b = static_cast<unsigned __int128>(gen_int128());
  const UInt256 p = multiply_wide(a, b);
  RC_ASSERT(((big(p.hi) << 128) | big(p.lo)) == cpp_int(a) * cpp_int(b));
}

}  // namespace
}  // namespace edgeland::test
