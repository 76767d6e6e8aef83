#pragma once
// Intervals along the sides of a cell: where solid lies on them (a cell's ports) or across them
// (its covers, from the neighbours' ports).
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "solid_boundary.hpp"

namespace edgeland::game_detail {

// A closed interval of positions along a side.
struct Span {
  std::int64_t lo = 0, hi = 0;
  friend bool operator==(const Span&, const Span&) = default;
};

// Intervals along each side of a cell, per Side: merged, ascending, disjoint.
struct SideSpans {
  std::array<std::vector<Span>, 4> sides;
  friend bool operator==(const SideSpans&, const SideSpans&) = default;
};

// Sorts the spans and joins touching or overlapping ones: a union, the same whichever way the
// polygons happen to be cut along the line.
inline void merge_spans(std::vector<Span>& spans) {
  std::sort(spans.begin(), spans.end(), [](const Span& l, const Span& r) { return l.lo < r.lo; });
  std::size_t kept = 0;
  for (const Span& s : spans) {
    if (kept > 0 && s.lo <= spans[kept - 1].hi)
      spans[kept - 1].hi = std::max(spans[kept - 1].hi, s.hi);
    else
      spans[kept++] = s;
  }
  spans.resize(kept);
}

// The extent of the box's side along it.
inline Span side_extent(const Box64& box, Side side) {
  return side == Side::kBottom || side == Side::kTop ? Span{box.min.x, box.max.x}
                                                     : Span{box.min.y, box.max.y};
}

}  // namespace edgeland::game_detail
