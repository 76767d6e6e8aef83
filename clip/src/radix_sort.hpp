#pragma once
// Sort by a 64-bit key, LSD radix for large inputs: the plane graph sorts tens of thousands of
// fragment ends per operation, and comparison sorts of them were a third of its time (and still
// a seventh of a 100-square checkerboard's at a few thousand). Bits on which all keys agree are
// skipped (coordinates of one input share their high bits), so typical inputs take three or
// four passes. Digits are 11 bits for large inputs and 8 below 4,096 elements, where counting
// 2,048 buckets per pass would dominate; below 512 a comparison sort wins (measured on point
// keys), and a handful of elements are insertion-sorted.
// Elements with equal keys may come out in any order: both callers' ties are interchangeable
// (equal fragment ends get one vertex id; equal stops of a segment are re-sorted by position
// along it). The order is still a deterministic function of the input. The comparison sort is
// std::sort, a quarter faster here than std::stable_sort and its buffer allocation.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/recycled_vector.hpp"

namespace edgeland::detail {

namespace radix_detail {

template <int kBits, class T, class KeyOf>
void lsd_passes(std::vector<T>& v, KeyOf& key_of) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << kBits) - 1;
  const std::uint64_t first = key_of(v[0]);
  std::uint64_t varying = 0;
  for (const T& x : v) varying |= key_of(x) ^ first;
  // The scatter buffer's storage is recycled (recycled_vector.hpp); after an odd number of
  // passes it and v have traded storage, which is as good.
  RecycledVector<struct RadixScatterBuffer, T> tmp;
  // Each digit starts at the lowest varying bit not yet sorted on: keys made of two 32-bit
  // halves that vary in their low bits only take one pass fewer than with fixed digits.
  for (int shift = 0; shift < 64 && (varying >> shift) != 0; shift += kBits) {
    shift += std::countr_zero(varying >> shift);
    if (tmp.empty()) tmp.resize(v.size());
    std::array<std::uint32_t, (std::size_t{1} << kBits) + 1> start{};
    for (const T& x : v) ++start[((key_of(x) >> shift) & kMask) + 1];
    for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    for (const T& x : v) tmp[start[(key_of(x) >> shift) & kMask]++] = x;
    v.swap(tmp);
  }
}

}  // namespace radix_detail

template <class T, class KeyOf>
void radix_sort(std::vector<T>& v, KeyOf key_of) {
  if (v.size() <= 32) {  // insertion sort: stable, no buffer
    for (std::size_t i = 1; i < v.size(); ++i) {
      T x = v[i];
      const std::uint64_t k = key_of(x);
      std::size_t j = i;
      for (; j > 0 && k < key_of(v[j - 1]); --j) v[j] = v[j - 1];
      v[j] = x;
    }
    return;
  }
  if (v.size() < 512) {  // the buckets' fixed cost would dominate
    std::sort(v.begin(), v.end(), [&](const T& a, const T& b) { return key_of(a) < key_of(b); });
  } else if (v.size() < 4096) {
    radix_detail::lsd_passes<8>(v, key_of);
  } else {
    radix_detail::lsd_passes<11>(v, key_of);
  }
}

}  // namespace edgeland::detail
