#pragma once
// A union-find over 0..n-1 (path halving, union by index: deterministic), its storage reused
// from one use to the next.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/scratch.hpp"

namespace edgeland::game_detail {

template <class Storage>
class BasicUnionFind {
 public:
  explicit BasicUnionFind(std::size_t n = 0) { reset(n); }
  void reset(std::size_t n) {
    parent_.resize(n);
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  std::size_t size() const { return parent_.size(); }

 private:
  Storage parent_;
};

// One kept in a long-lived object (a cell's scan).
using UnionFind = BasicUnionFind<std::vector<std::uint32_t>>;
// A temporary one on the thread's spare storage (scratch.hpp): no allocation once warm. Never a
// member of a long-lived object (its storage goes back to the thread's spares when it dies).
using ScratchUnionFind = BasicUnionFind<detail::ScratchVector<std::uint32_t>>;

}  // namespace edgeland::game_detail
