// int128_low, int128_high and int128_from_words (int128.hpp): an Int128's bits as two words and
// back, for binary formats (region records store areas so).
#include <gtest/gtest.h>

#include <limits>

#include "edgeland/kernel/int128.hpp"

namespace edgeland {
namespace {

TEST(Int128Words, EveryValueComesBackFromItsTwoWords) {
  const Int128 max = std::numeric_limits<Int128>::max(), min = std::numeric_limits<Int128>::min();
  for (const Int128 v : {Int128{0}, Int128{1}, Int128{-1}, max, min, max / 3, min / 7,
                         static_cast<Int128>(std::numeric_limits<std::int64_t>::min()) - 1}) {
    EXPECT_EQ(int128_from_words(int128_low(v), int128_high(v)), v) << to_string(v);
  }
  EXPECT_EQ(int128_low(-1), ~std::uint64_t{0});
  EXPECT_EQ(int128_high(-1), ~std::uint64_t{0});
  EXPECT_EQ(int128_high(Int128{1} << 64), 1u);
  EXPECT_EQ(int128_low(Int128{1} << 64), 0u);
}

}  // namespace
}  // namespace edgeland
