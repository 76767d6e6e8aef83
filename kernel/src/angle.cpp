#include "edgeland/kernel/angle.hpp"

#include "edgeland/kernel/predicates.hpp"

namespace edgeland {
namespace {

bool same_direction(Point64 a, Point64 b) {
  return orientation({0, 0}, a, b) == Orientation::kCollinear && dot_sign({0, 0}, a, b) > 0;
}

}  // namespace

bool strictly_inside_ccw_sector(Point64 from, Point64 to, Point64 d) noexcept {
  if (same_direction(d, from) || same_direction(d, to)) return false;
  // Measure every angle relative to `from`: d is inside when it comes before `to`.
  const bool to_before_from = angle_less(to, from);
  const bool d_before_from = angle_less(d, from);
  const bool d_before_to = angle_less(d, to);
  if (!to_before_from) return !d_before_from && d_before_to;  // from < d < to
  return !d_before_from || d_before_to;                       // wraps past angle 0
}

}  // namespace edgeland
