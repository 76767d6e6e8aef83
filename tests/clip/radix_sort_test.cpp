// radix_sort (clip/src/radix_sort.hpp) against std::stable_sort: the output is ordered by key and
// is a permutation of the input. Sizes cover every path (insertion, comparison, 8-bit digits
// with four lanes, 11-bit digits with two, lanes of unequal length); keys are clustered (long
// runs of one digit, what the lanes are for), spread over all 64 bits, or few and repeated.
// counting_sort, beside it, against std::stable_sort by id.
#include "radix_sort.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace edgeland::detail {
namespace {

using Item = std::pair<std::uint64_t, std::uint32_t>;  // (key, original index)

void expect_sorted_permutation(std::vector<Item> items) {
  std::vector<Item> expected = items;
  std::stable_sort(expected.begin(), expected.end(),
                   [](const Item& a, const Item& b) { return a.first < b.first; });
  radix_sort(items, [](const Item& x) { return x.first; });
  RC_ASSERT(std::is_sorted(items.begin(), items.end(),
                           [](const Item& a, const Item& b) { return a.first < b.first; }));
  // Ties may come out in any order: compare as multisets of (key, index).
  std::sort(items.begin(), items.end());
  std::sort(expected.begin(), expected.end());
  RC_ASSERT(items == expected);
}

rc::Gen<std::uint64_t> key() {
  return rc::gen::oneOf(
      rc::gen::arbitrary<std::uint64_t>(), rc::gen::inRange<std::uint64_t>(0, 4),
      rc::gen::map(rc::gen::inRange<std::uint64_t>(0, 1 << 20), [](std::uint64_t v) {
        // Two 32-bit halves, as point keys are: high bits shared.
        return (std::uint64_t{0x80000000u} + (v >> 10)) << 32 | (0x7fff0000u + (v & 1023));
      }));
}

RC_GTEST_PROP(RadixSort, SortsByKeyAndKeepsEveryElement, ()) {
  const auto size = *rc::gen::element<std::size_t>(0, 1, 2, 31, 33, 511, 512, 513, 515, 4095, 4096,
                                                   4097, 4099, 9001);
  const auto keys = *rc::gen::container<std::vector<std::uint64_t>>(size, key());
  std::vector<Item> items(size);
  for (std::uint32_t i = 0; i < size; ++i) items[i] = {keys[i], i};
  expect_sorted_permutation(std::move(items));
}

RC_GTEST_PROP(CountingSort, EqualsAStableSortById, ()) {
  const auto buckets = *rc::gen::inRange<std::size_t>(1, 2000);
  const auto ids =
      *rc::gen::container<std::vector<std::uint64_t>>(rc::gen::inRange<std::uint64_t>(0, buckets));
  std::vector<Item> items(ids.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) items[i] = {ids[i], i};
  std::vector<Item> expected = items;
  std::stable_sort(expected.begin(), expected.end(),
                   [](const Item& a, const Item& b) { return a.first < b.first; });
  counting_sort(items, buckets, [](const Item& x) { return x.first; });
  RC_ASSERT(items == expected);  // stable: equal ids keep their input order
}

TEST(RadixSort, RunsOfOneDigitAcrossLaneBoundaries) {
  // Already sorted, reversed, and constant blocks whose lengths do not divide the lane size.
  for (const std::size_t n : {std::size_t{603}, std::size_t{5001}}) {
    std::vector<Item> up(n), down(n), blocks(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      up[i] = {std::uint64_t{i} << 20, i};
      down[i] = {std::uint64_t{n - i} << 40, i};
      blocks[i] = {std::uint64_t{i / 37} * 0x0101010101ull, i};
    }
    for (auto* v : {&up, &down, &blocks}) {
      std::vector<Item> sorted = *v;
      radix_sort(sorted, [](const Item& x) { return x.first; });
      EXPECT_TRUE(std::is_sorted(sorted.begin(), sorted.end(),
                                 [](const Item& a, const Item& b) { return a.first < b.first; }));
      std::sort(sorted.begin(), sorted.end());
      std::vector<Item> expected = *v;
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(sorted, expected);
    }
  }
}

}  // namespace
}  // namespace edgeland::detail
