#include "canonical.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {

Ring canonical_ring(Ring ring) {
  // Drop vertices that lie on the straight line through their neighbours. In a simple ring
  // with nonzero area a collinear vertex is a straight continuation, never a fold-back.
  // In place: the kept prefix [0, w) never overtakes the point being read.
  Ring& out = ring;
  std::size_t w = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Point64 p = out[i];
    while (w >= 2 && orientation(out[w - 2], out[w - 1], p) == Orientation::kCollinear) --w;
    out[w++] = p;
  }
  out.resize(w);
  // The seam: the first and last vertices may be collinear with their wrap-around neighbours.
  bool changed = true;
  while (changed && out.size() > 3) {
    changed = false;
    const std::size_t n = out.size();
    if (orientation(out[n - 2], out[n - 1], out[0]) == Orientation::kCollinear) {
      out.pop_back();
      changed = true;
    } else if (orientation(out[n - 1], out[0], out[1]) == Orientation::kCollinear) {
      out.erase(out.begin());
      changed = true;
    }
  }
  // Start at the least vertex. Small rings rotate in place; large ones take two block copies
  // into a new ring (std::rotate swaps element by element, several times slower on rings of
  // thousands of vertices, while an allocation per small ring costs more than its rotation).
  const auto least = std::min_element(out.begin(), out.end());
  if (least == out.begin()) return ring;
  if (out.size() <= 256) {
    std::rotate(out.begin(), least, out.end());
    return ring;
  }
  Ring rotated;
  rotated.reserve(out.size());
  rotated.insert(rotated.end(), least, out.end());
  rotated.insert(rotated.end(), out.begin(), least);
  return rotated;
}

void canonicalize(PolygonSet& set) {
  for (Polygon& p : set) p = canonical_ring(std::move(p));
  // Sorted by first (least) vertex, which polygons share only when they touch there: the
  // comparisons read one point kept next to its index, not two rings through their pointers.
  struct Key {
    Point64 first;
    std::uint32_t index;
  };
  std::vector<Key> keys(set.size());
  for (std::uint32_t i = 0; i < keys.size(); ++i)
    keys[i] = {set[i].empty() ? Point64{} : set[i].front(), i};
  std::sort(keys.begin(), keys.end(), [&](const Key& x, const Key& y) {
    const bool decided = x.first != y.first && !set[x.index].empty() && !set[y.index].empty();
    return decided ? x.first < y.first : set[x.index] < set[y.index];  // = lexicographic
  });
  PolygonSet sorted;
  sorted.reserve(set.size());
  for (const Key& k : keys) sorted.push_back(std::move(set[k.index]));
  set.swap(sorted);
}

}  // namespace edgeland::detail
