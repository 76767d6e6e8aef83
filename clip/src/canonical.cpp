#include "canonical.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "point_key.hpp"

namespace edgeland::detail {

Ring canonical_ring(Ring ring) {
  // The one-pass builder with every point tested: in a simple ring with nonzero area a
  // collinear vertex is a straight continuation, never a fold-back. Built in scratch storage
  // and copied back into the ring's own (it only loses points): no allocation.
  const auto least =
      static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
  int turn = 0;
  ScratchVector<Point64> out;
  canonical_ring_into(ring, nullptr, least, turn, out);
  ring.assign(out.begin(), out.end());
  return ring;
}

namespace {

// The stack algorithm for points marked by `check` (canonical_ring_from), appended to out.
void canonical_marked(const std::vector<Point64>& points, const std::uint8_t* check,
                      std::size_t least, Ring& out) {
  const std::size_t n = points.size();
  // The stack algorithm of canonical_ring, from the smallest point round: the top is dropped
  // while it is collinear with its neighbours. A top needs the test if it is marked, or if its
  // left neighbour on the stack is not its own predecessor (something between was dropped), or
  // if its right neighbour is not its successor (the point being added after a drop).
  // suspect[k]: out[k] must be tested once it is the middle of three.
  ScratchVector<std::uint8_t> suspect;
  suspect.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = least + k < n ? least + k : least + k - n;
    const Point64 p = points[i];
    bool dropped = false;
    const bool tested = check[i] != 0;
    while (out.size() >= 2 && (tested || suspect.back() || dropped) &&
           orientation(out[out.size() - 2], out.back(), p) == Orientation::kCollinear) {
      out.pop_back();
      suspect.pop_back();
      dropped = true;
    }
    if (dropped && !suspect.empty()) suspect.back() = 1;  // its right neighbour changed
    out.push_back(p);
    suspect.push_back(static_cast<std::uint8_t>(tested || dropped));
  }
}

}  // namespace

Ring canonical_ring_from(const std::vector<Point64>& points, const std::uint8_t* check,
                         std::size_t least, int& turn) {
  Ring out;
  canonical_ring_into(points, check, least, turn, out);
  return out;
}

void canonical_ring_into(const std::vector<Point64>& points, const std::uint8_t* check,
                         std::size_t least, int& turn, Ring& out) {
  const std::size_t n = points.size();
  out.clear();
  turn = 0;
  if (n < 3) return;
  out.reserve(n);
  if (check == nullptr) {
    // Every point tested: the plain stack algorithm, nothing to remember about drops.
    for (std::size_t k = 0; k < n; ++k) {
      const Point64 p = points[least + k < n ? least + k : least + k - n];
      while (out.size() >= 2 &&
             orientation(out[out.size() - 2], out.back(), p) == Orientation::kCollinear)
        out.pop_back();
      out.push_back(p);
    }
  } else {
    canonical_marked(points, check, least, out);
  }
  // The seam: the smallest point (out[0]) is never collinear between its neighbours (both are
  // larger), but the last points may be collinear with it.
  while (out.size() > 3 &&
         orientation(out[out.size() - 2], out.back(), out[0]) == Orientation::kCollinear)
    out.pop_back();
  if (out.size() < 3) return;
  turn = static_cast<int>(orientation(out.back(), out[0], out[1]));
}

bool collinear_free(const PolygonSet& set) {
  for (const Polygon& ring : set) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i)
      if (orientation(ring[i == 0 ? n - 1 : i - 1], ring[i], ring[i + 1 == n ? 0 : i + 1]) ==
          Orientation::kCollinear)
        return false;
  }
  return true;
}

void sort_canonical(PolygonSet& set, std::vector<std::int64_t>* labels) {
  // Sorted by first (least) vertex, which polygons share only when they touch there: the
  // comparisons read one 64-bit key kept next to the index (the point, shifted into unsigned
  // 32-bit halves: order-preserving for in-range coordinates; 0 for an empty ring, which sorts
  // first as lexicographic order wants), not two rings through their pointers.
  struct Key {
    std::uint64_t first;
    std::uint32_t index;
  };
  auto key_of = [](const Polygon& p) -> std::uint64_t {
    if (p.empty()) return 0;
    if (!in_range(p.front())) fail_stage("canonical order", "vertex out of range");
    return point_key(p.front());
  };
  // Permuted through scratch arrays, so the set and the labels keep their storage.
  ScratchVector<Key> keys;
  keys.resize(set.size());
  for (std::uint32_t i = 0; i < keys.size(); ++i) keys[i] = {key_of(set[i]), i};
  std::sort(keys.begin(), keys.end(), [&](const Key& x, const Key& y) {
    return x.first != y.first ? x.first < y.first : set[x.index] < set[y.index];
  });
  ScratchVector<Polygon> sorted;
  sorted.reserve(set.size());
  for (const Key& k : keys) sorted.push_back(std::move(set[k.index]));
  for (std::size_t i = 0; i < sorted.size(); ++i) set[i] = std::move(sorted[i]);
  if (!labels) return;
  ScratchVector<std::int64_t> permuted;
  permuted.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) permuted[i] = (*labels)[keys[i].index];
  labels->assign(permuted.begin(), permuted.end());
}

void drop_collinear_except(Ring& ring, const std::vector<Point64>& keep) {
  // The stack algorithm of canonical_ring from a point that stays (a corner: the smallest
  // point of a simple ring is one), testing only points not in `keep`; built in scratch
  // storage and copied back into the ring's own.
  const std::size_t n = ring.size();
  const auto least =
      static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
  auto droppable = [&](Point64 p) { return !std::binary_search(keep.begin(), keep.end(), p); };
  ScratchVector<Point64> out;
  out.reserve(n);
  for (std::size_t k = 0; k <= n; ++k) {
    const Point64 p = ring[(least + k) % n];
    while (out.size() >= 2 && droppable(out.back()) &&
           orientation(out[out.size() - 2], out.back(), p) == Orientation::kCollinear)
      out.pop_back();
    if (k < n) out.push_back(p);
  }
  ring.assign(out.begin(), out.end());
}

}  // namespace edgeland::detail
