#pragma once
// Axis-aligned bounding boxes (thesis 4.1): the first, O(1) filter before any exact test.
#include <algorithm>
#include <optional>

#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

// Closed box [min.x, max.x] x [min.y, max.y]; min <= max componentwise.
struct Box64 {
  Point64 min;
  Point64 max;
  friend constexpr bool operator==(const Box64&, const Box64&) = default;

  constexpr bool contains(Point64 p) const noexcept {
    return min.x <= p.x && p.x <= max.x && min.y <= p.y && p.y <= max.y;
  }
  // Closed boxes: touching counts as overlapping.
  constexpr bool overlaps(const Box64& o) const noexcept {
    return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y;
  }
  constexpr void expand(Point64 p) noexcept {
    min.x = std::min(min.x, p.x);
    min.y = std::min(min.y, p.y);
    max.x = std::max(max.x, p.x);
    max.y = std::max(max.y, p.y);
  }
  constexpr void expand(const Box64& o) noexcept {
    expand(o.min);
    expand(o.max);
  }
};

// O(n). nullopt for an empty ring.
inline std::optional<Box64> bounding_box(const Ring& ring) noexcept {
  if (ring.empty()) return std::nullopt;
  Box64 box{ring.front(), ring.front()};
  for (const Point64& p : ring) box.expand(p);
  return box;
}

// O(total vertices). nullopt when every member is empty.
inline std::optional<Box64> bounding_box(const PolygonSet& set) noexcept {
  std::optional<Box64> box;
  for (const Polygon& p : set) {
    if (auto b = bounding_box(p)) {
      if (box)
        box->expand(*b);
      else
        box = b;
    }
  }
  return box;
}

}  // namespace edgeland
