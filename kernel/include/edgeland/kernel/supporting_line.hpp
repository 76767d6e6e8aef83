#pragma once
// The line through a segment as a sortable key: segments on one line, in either direction, get
// equal keys, so finding where two boundaries lie on each other is a sort and a merge of
// intervals. The game layer (game/) uses it to tell contacts between solid polygons (shared
// boundary of positive length) from surfaces (solid on one side only).
#include <compare>
#include <cstdint>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland {

struct SupportingLine {
  // (b - a) divided by the gcd of its components, turned to point to +x (to +y when vertical):
  // the line's canonical direction.
  Point64 direction;
  // cross(direction, p), the same for every point p of the line (formulas::line_offset,
  // theorem line_offset_int128).
  Int128 offset = 0;
  friend bool operator==(const SupportingLine&, const SupportingLine&) = default;
  friend bool operator<(const SupportingLine& l, const SupportingLine& r) noexcept {
    if (l.direction != r.direction) return l.direction < r.direction;
    return l.offset < r.offset;
  }
};

// The line through a and b (a != b, both in range). O(log |b - a|) (a gcd).
EDGELAND_EXPORT SupportingLine supporting_line(Point64 a, Point64 b) noexcept;

// Where p lies along the line, increasing in its direction: p.x, or p.y on a vertical line. Only
// meaningful for points of the line. O(1).
constexpr std::int64_t position_on(const SupportingLine& line, Point64 p) noexcept {
  return line.direction.x != 0 ? p.x : p.y;
}

// Whether a -> b (two points of the line) runs in the line's direction. O(1).
constexpr bool runs_forward(const SupportingLine& line, Point64 a, Point64 b) noexcept {
  return position_on(line, a) < position_on(line, b);
}

}  // namespace edgeland
