#pragma once
// Axis-aligned boxes (thesis 4.1): the first, O(1) filter before any exact test, and the cells
// of the landscape. One vocabulary for every folder: closed containment and overlap, overlap
// beyond the boundary (open intervals), the half-open rule of cells, a box with an interior, its
// boundary ring, a segment's box. All are comparisons of coordinates.
#include <algorithm>
#include <array>
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
  // The closed box o (min <= max) lies in this one (sharing boundary counts).
  constexpr bool contains(const Box64& o) const noexcept {
    return min.x <= o.min.x && o.max.x <= max.x && min.y <= o.min.y && o.max.y <= max.y;
  }
  // The half-open rule of cells: p in [min.x, max.x) x [min.y, max.y), so a point on a shared
  // side belongs to exactly one of two boxes that meet there (the one above or to the right).
  constexpr bool holds_half_open(Point64 p) const noexcept {
    return min.x <= p.x && p.x < max.x && min.y <= p.y && p.y < max.y;
  }
  // Closed boxes: touching counts as overlapping.
  constexpr bool overlaps(const Box64& o) const noexcept {
    return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y;
  }
  // Overlap beyond the boundary: open intervals on both axes (min < o.max and o.min < max), so
  // boxes that only touch along a side or at a corner do not overlap. For boxes with an
  // interior, whether their interiors share a point.
  constexpr bool overlaps_open(const Box64& o) const noexcept {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
  // Positive width and height.
  constexpr bool has_interior() const noexcept { return min.x < max.x && min.y < max.y; }
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

// The corners counter-clockwise from min: min, (max.x, min.y), max, (min.x, max.y).
constexpr std::array<Point64, 4> box_corners(const Box64& b) noexcept {
  return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
}

// The boundary as a counter-clockwise ring from min (box_corners): a valid polygon when the
// box has an interior.
inline Ring box_ring(const Box64& b) {
  const std::array<Point64, 4> c = box_corners(b);
  return Ring(c.begin(), c.end());
}

// The closed box of segment a-b (or of s).
constexpr Box64 segment_box(Point64 a, Point64 b) noexcept {
  return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}
constexpr Box64 segment_box(const Segment& s) noexcept { return segment_box(s.a, s.b); }

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
