#pragma once
// A set of integer points in one flat array (open addressing, linear probing): snap rounding's
// hot-pixel set. std::unordered_set allocated a node per hot pixel, thousands per operation on
// spiky inputs. Membership only, so iteration order (which would depend on hashing) is never
// exposed: results cannot depend on it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

class PointSet {
 public:
  // Inserts p (any point but the reserved one below); false if it was there already.
  bool insert(Point64 p) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t i = home(p);
    while (slots_[i] != kEmpty) {
      if (slots_[i] == p) return false;
      i = (i + 1) & (slots_.size() - 1);
    }
    slots_[i] = p;
    ++size_;
    return true;
  }
  bool contains(Point64 p) const {
    if (size_ == 0) return false;
    for (std::size_t i = home(p);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i] == p) return true;
      if (slots_[i] == kEmpty) return false;
    }
  }
  std::size_t size() const { return size_; }
  // Room for `count` points without growing.
  void reserve(std::size_t count) {
    std::size_t want = 16;
    while (want < 2 * count) want *= 2;
    if (want <= slots_.size()) return;
    ScratchVector<Point64> old;
    old.assign(want, kEmpty);
    old.swap(slots_);
    size_ = 0;
    for (Point64 p : old)
      if (p != kEmpty) insert(p);
  }
  void clear() {
    slots_.assign(slots_.size(), kEmpty);
    size_ = 0;
  }

 private:
  // Far outside the coordinate range (point.hpp), so never a member.
  static constexpr Point64 kEmpty{std::numeric_limits<std::int64_t>::min(),
                                  std::numeric_limits<std::int64_t>::min()};
  std::size_t home(Point64 p) const { return Point64Hash{}(p) & (slots_.size() - 1); }
  void grow() { reserve(std::max<std::size_t>(8, slots_.size())); }
  ScratchVector<Point64> slots_;  // a power of two in size, at most half full
  std::size_t size_ = 0;
};

}  // namespace edgeland::detail
