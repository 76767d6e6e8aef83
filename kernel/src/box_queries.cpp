// Segments and rings against boxes (box_queries.hpp).
#include "edgeland/kernel/box_queries.hpp"

#include <algorithm>

#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {
namespace {

// [lo, hi] of t with lo_c <= a + t d <= hi_c along one axis (d != 0): (c - a) / d, ordered.
// Differences of in-range coordinates fit 33 bits.
void axis_range(std::int64_t a, std::int64_t d, std::int64_t lo_c, std::int64_t hi_c, Fraction& lo,
                Fraction& hi) {
  Fraction t_lo{Int128(lo_c) - a, d}, t_hi{Int128(hi_c) - a, d};
  if (d < 0) {
    t_lo = {-t_lo.num, -t_lo.den};
    t_hi = {-t_hi.num, -t_hi.den};
    std::swap(t_lo, t_hi);
  }
  lo = t_lo;
  hi = t_hi;
}

const Fraction& max_of(const Fraction& x, const Fraction& y) { return compare(x, y) >= 0 ? x : y; }
const Fraction& min_of(const Fraction& x, const Fraction& y) { return compare(x, y) <= 0 ? x : y; }

}  // namespace

std::optional<ParameterRange> clip_parameters(const Segment& s, const Box64& box) noexcept {
  const std::int64_t dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  Fraction t0{0, 1}, t1{1, 1};
  for (int axis = 0; axis < 2; ++axis) {
    const std::int64_t a = axis == 0 ? s.a.x : s.a.y, d = axis == 0 ? dx : dy;
    const std::int64_t lo_c = axis == 0 ? box.min.x : box.min.y;
    const std::int64_t hi_c = axis == 0 ? box.max.x : box.max.y;
    if (d == 0) {
      if (a < lo_c || a > hi_c) return std::nullopt;
      continue;
    }
    Fraction lo, hi;
    axis_range(a, d, lo_c, hi_c, lo, hi);
    t0 = max_of(t0, lo);
    t1 = min_of(t1, hi);
    if (compare(t0, t1) > 0) return std::nullopt;
  }
  return ParameterRange{t0, t1};
}

bool segment_meets_open_box(const Segment& s, const Box64& box) noexcept {
  if (!box.has_interior()) return false;
  if (!segment_box(s).overlaps_open(box)) return false;  // apart along x or y
  if (s.a == s.b) return true;                           // inside both open ranges
  bool left = false, right = false;
  for (Point64 c : box_corners(box)) {
    const Orientation o = orientation(s.a, s.b, c);
    left = left || o == Orientation::kCounterClockwise;
    right = right || o == Orientation::kClockwise;
  }
  return left && right;
}

bool interiors_overlap(const Box64& box, const Ring& ring) noexcept {
  if (!box.has_interior() || ring.size() < 3) return false;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
    if (segment_meets_open_box({ring[i], ring[i + 1 == n ? 0 : i + 1]}, box)) return true;
  // The boundary misses the open box, which is therefore wholly inside or wholly outside;
  // min + eps (1, eps) is one of its points.
  return inside_half_open(box.min, ring);
}

}  // namespace edgeland
