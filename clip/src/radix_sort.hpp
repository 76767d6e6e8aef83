#pragma once
// Stable LSD radix sort by a 64-bit key: the plane graph sorts tens of thousands of fragment ends
// per operation, and comparison sorts of them were a third of its time. Eleven-bit digits; a
// digit position on which all keys agree is skipped (coordinates of one input share their high
// bits), so typical inputs take three or four passes.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace edgeland::detail {

template <class T, class KeyOf>
void radix_sort(std::vector<T>& v, KeyOf key_of) {
  if (v.size() < 4096) {  // counting 2048 buckets per pass would dominate
    std::stable_sort(v.begin(), v.end(),
                     [&](const T& a, const T& b) { return key_of(a) < key_of(b); });
    return;
  }
  constexpr int kBits = 11;
  constexpr std::uint64_t kMask = (1u << kBits) - 1;
  const std::uint64_t first = key_of(v[0]);
  std::uint64_t varying = 0;
  for (const T& x : v) varying |= key_of(x) ^ first;
  std::vector<T> tmp(v.size());
  for (int shift = 0; shift < 64; shift += kBits) {
    if (((varying >> shift) & kMask) == 0) continue;
    std::array<std::uint32_t, (1u << kBits) + 1> start{};
    for (const T& x : v) ++start[((key_of(x) >> shift) & kMask) + 1];
    for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    for (const T& x : v) tmp[start[(key_of(x) >> shift) & kMask]++] = x;
    v.swap(tmp);
  }
}

}  // namespace edgeland::detail
