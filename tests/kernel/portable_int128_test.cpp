// PortableInt128 / PortableUInt128 (kernel/.../portable_int128.hpp) against the compiler's
// __int128, operation by operation: every pair of a table of edge values (0, +-1, the word
// boundaries, the extremes, powers of two and their neighbours) and random pairs. Runs in both
// builds: in the portable one (-DEDGELAND_PORTABLE_INT128=ON) Int128 is the class under test,
// in the native one the class is still what MSVC would compile. The fuzz target
// int128_portable does the same on decoded bytes (fuzz/int128_decoders.cpp).
#include "edgeland/kernel/portable_int128.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/int128.hpp"
#include "support/int128_differential.hpp"

namespace edgeland {
namespace {

using Native = test::NativeInt128;
using NativeU = test::NativeUInt128;
using test::first_difference;
using test::native;
using test::portable;

constexpr Native kMin = std::numeric_limits<Native>::min();
constexpr Native kMax = std::numeric_limits<Native>::max();

std::vector<Native> edge_values() {
  std::vector<Native> out{0, 1, -1, 2, -2, 3, 10, -10, kMin, kMax, kMin + 1, kMax - 1};
  for (int k = 1; k < 127; ++k) {
    const Native p = Native{1} << k;
    for (const Native v : {p, p - 1, p + 1, -p, -p + 1, -p - 1}) out.push_back(v);
  }
  out.push_back(static_cast<Native>(~std::uint64_t{0}));  // the low word full
  out.push_back(static_cast<Native>(0x123456789abcdef0ULL) * 0x0fedcba987654321LL);
  return out;
}

TEST(PortableInt128, AgreesWithTheNativeTypeOnEveryPairOfEdgeValues) {
  const std::vector<Native> values = edge_values();
  for (const Native a : values) {
    for (const Native b : values) {
      const char* op = first_difference(a, b);
      ASSERT_EQ(op, nullptr) << op << " on edge values " << (&a - values.data()) << " and "
                             << (&b - values.data());
    }
  }
}

RC_GTEST_PROP(PortableInt128, AgreesWithTheNativeTypeOnRandomValues,
              (std::uint64_t a_lo, std::uint64_t a_hi, std::uint64_t b_lo, std::uint64_t b_hi,
               unsigned a_bits, unsigned b_bits)) {
  // Random widths too: most products in the kernel are of values far below 2^127.
  const auto make = [](std::uint64_t lo, std::uint64_t hi, unsigned bits) {
    const Native full = static_cast<Native>((static_cast<NativeU>(hi) << 64) | lo);
    return full >> (bits % 128);
  };
  const Native a = make(a_lo, a_hi, a_bits), b = make(b_lo, b_hi, b_bits);
  const char* op = first_difference(a, b);
  RC_ASSERT(op == nullptr);
}

// Conversions to double round once, to nearest, ties to even: the sticky bit must keep a value
// just above a halfway point above it, and a true halfway point must go to the even neighbour.
TEST(PortableInt128, ConvertsToDoubleRoundingTiesToEven) {
  const Native base = Native{1} << 100;  // doubles here are 2^48 apart
  const Native ulp = Native{1} << 48, half = ulp / 2;
  for (const Native v :
       {base + half, base + half + 1, base + half - 1, base + ulp + half, base + ulp + half + 1,
        -(base + half), -(base + ulp + half), kMax, kMin, kMax - half}) {
    EXPECT_EQ(static_cast<double>(portable(v)), static_cast<double>(v));
  }
  EXPECT_EQ(static_cast<double>(portable(base + half)), std::ldexp(1.0, 100));
  EXPECT_EQ(static_cast<double>(portable(base + ulp + half)),
            std::ldexp(1.0, 100) + 2 * std::ldexp(1.0, 48));
  EXPECT_EQ(static_cast<double>(portable(kMax)), std::ldexp(1.0, 127));
}

TEST(PortableInt128, IsAConstantExpression) {
  static_assert((PortableInt128{1} << 62) == PortableInt128{std::int64_t{1} << 62});
  static_assert(PortableInt128{-7} / 2 == -3 && PortableInt128{-7} % 2 == -1);
  static_assert(std::numeric_limits<PortableInt128>::max() + 1 ==
                std::numeric_limits<PortableInt128>::min());
  static_assert(static_cast<std::int64_t>(PortableInt128{-5} >> 1) == -3);
  static_assert(sizeof(PortableInt128) == 16 && std::is_trivially_copyable_v<PortableInt128>);
}

// The words of an Int128 (what the C API's el_int128 carries) round-trip in both builds.
TEST(Int128Words, RoundTripTheExtremes) {
  for (const Int128 v : {Int128(0), Int128(-1), Int128(1) << 100, -(Int128(1) << 100),
                         std::numeric_limits<Int128>::max(), std::numeric_limits<Int128>::min()}) {
    EXPECT_EQ(from_words(to_words(v)), v);
  }
  EXPECT_EQ(to_words(Int128(-1)).hi, -1);
  EXPECT_EQ(to_words(Int128(-1)).lo, ~std::uint64_t{0});
  EXPECT_EQ(to_words(Int128(1) << 64).hi, 1);
}

// The overflow tests of the checked arithmetic: the builtins natively, the sign-bit tests in the
// portable build; both against the exact answer.
TEST(CheckedArithmetic, OverflowTestsAgreeWithTheExactResult) {
  const std::int64_t big = std::numeric_limits<std::int64_t>::max();
  const std::int64_t small = std::numeric_limits<std::int64_t>::min();
  for (const std::int64_t a : {big, small, big - 1, small + 1, std::int64_t{0}, std::int64_t{-1},
                               std::int64_t{3037000500}, std::int64_t{-3037000500}}) {
    for (const std::int64_t b : {big, small, std::int64_t{1}, std::int64_t{-1}, std::int64_t{2},
                                 std::int64_t{3037000500}, std::int64_t{-3037000499}}) {
      std::int64_t r = 0;
      const Native sum = Native{a} + b, difference = Native{a} - b, product = Native{a} * b;
      const auto fits = [](Native v) { return v >= INT64_MIN && v <= INT64_MAX; };
      EXPECT_EQ(arith::add_overflows(a, b, &r), !fits(sum));
      EXPECT_EQ(arith::sub_overflows(a, b, &r), !fits(difference));
      EXPECT_EQ(arith::mul_overflows(a, b, &r), !fits(product));
      if (fits(product)) EXPECT_EQ(r, product);
    }
  }
  const Int128 top = std::numeric_limits<Int128>::max(),
               bottom = std::numeric_limits<Int128>::min();
  Int128 r = 0;
  EXPECT_TRUE(arith::add_overflows(top, Int128(1), &r));
  EXPECT_FALSE(arith::add_overflows(top, Int128(-1), &r));
  EXPECT_TRUE(arith::sub_overflows(bottom, Int128(1), &r));
  EXPECT_FALSE(arith::sub_overflows(Int128(-1), bottom, &r));
  EXPECT_EQ(r, top);
  EXPECT_TRUE(arith::mul_overflows(Int128(1) << 64, Int128(1) << 63, &r));
  EXPECT_FALSE(arith::mul_overflows(-(Int128(1) << 64), Int128(1) << 63, &r));
  EXPECT_EQ(r, bottom);
}

}  // namespace
}  // namespace edgeland
