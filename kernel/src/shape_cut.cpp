// cut_to_bound (shape_hull.hpp): one side at a time, always the east side x <= kCoordBound of a
// copy turned by a quarter (the box is symmetric, and a quarter turn (x, y) -> (-y, x) keeps
// orientation), so one cut serves all four sides; four turns bring the polygon back.
#include <algorithm>
#include <cstddef>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/point.hpp"
#include "shape_hull.hpp"

namespace edgeland::detail {
namespace {

using W = arith::Checked<Int128>;

// The integer y nearest the crossing of segment a -> b (a.x < limit < b.x) with x = limit on
// the shape's side: the crossing lies at ay + num / den, and `up` rounds it up (ceil), else down.
std::int64_t crossing_y(std::int64_t limit, Point64 a, Point64 b, bool up) {
  const W num = formulas::crossing_numerator<W>(limit, a.x, a.y, b.y), den = W(b.x) - W(a.x);
  const W y = up ? W(a.y) - floor_div(-num, den) : W(a.y) + floor_div(num, den);
  return static_cast<std::int64_t>(y.v);
}

// The polygon's part with x <= limit, as points whose hull it is: the corners on that side and
// where the boundary crosses the line, rounded inward. The ring runs counter-clockwise, so it
// leaves the side (going east) at the low end of its chord on the line and comes back (going
// west) at the high end: the first rounds up, the second down. When no integer lies between
// them, neither point is inside the polygon and both are left out.
std::vector<Point64> cut_east(const Polygon& ring, std::int64_t limit) {
  std::vector<Point64> out;
  std::int64_t low = 0, high = 0;
  std::size_t low_at = ring.size(), high_at = ring.size();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 p = ring[i], q = ring[(i + 1) % ring.size()];
    if (p.x <= limit) out.push_back(p);
    if (p.x < limit && q.x > limit) {
      low = crossing_y(limit, p, q, true);
      low_at = out.size();
      out.push_back({limit, low});
    } else if (p.x > limit && q.x < limit) {
      high = crossing_y(limit, q, p, false);
      high_at = out.size();
      out.push_back({limit, high});
    }
  }
  if (low_at < out.size() && high_at < out.size() && low > high) {
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(std::max(low_at, high_at)));
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(std::min(low_at, high_at)));
  }
  return out;
}

Polygon quarter_turn(Polygon ring) {
  for (Point64& p : ring) p = {-p.y, p.x};
  return ring;
}

}  // namespace

Polygon cut_to_bound(Polygon convex) {
  for (int side = 0; side < 4; ++side) {
    if (convex.size() >= 3) convex = convex_hull(cut_east(convex, kCoordBound));
    convex = quarter_turn(std::move(convex));
  }
  return convex;
}

}  // namespace edgeland::detail
