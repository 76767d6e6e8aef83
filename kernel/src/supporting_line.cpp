#include "edgeland/kernel/supporting_line.hpp"

#include <numeric>

#include "edgeland/kernel/formulas.hpp"

namespace edgeland {

SupportingLine supporting_line(Point64 a, Point64 b) noexcept {
  // Differences of in-range coordinates fit 33 bits (theorem orient_differences_int64), so
  // neither they nor their gcd can overflow int64.
  std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t g = std::gcd(dx, dy);
  dx /= g;
  dy /= g;
  if (dx < 0 || (dx == 0 && dy < 0)) {
    dx = -dx;
    dy = -dy;
  }
  return {{dx, dy}, formulas::line_offset<Int128>(dx, dy, a.x, a.y)};
}

}  // namespace edgeland
