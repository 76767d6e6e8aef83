#include "edgeland/kernel/convexity.hpp"

#include <cstddef>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland {
namespace {

constexpr int sign(std::int64_t v) noexcept { return (v > 0) - (v < 0); }

}  // namespace

bool is_convex(const Ring& ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  int turn = 0;           // the one sign every non-straight turn must have
  int first_dx_sign = 0;  // the x-direction of the first edge that has one
  int last_dx_sign = 0;
  int dx_sign_changes = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i];
    const Point64 b = ring[(i + 1) % n];
    const Point64 c = ring[(i + 2) % n];
    if (a == b) return false;
    const int o = static_cast<int>(orientation(a, b, c));
    if (o == 0) {
      // Straight vertex: fine when b continues forward, a fold-back when it turns around.
      if (b != c && dot_sign(b, c, a) > 0) return false;
    } else if (turn == 0) {
      turn = o;
    } else if (o != turn) {
      return false;
    }
    // Count how often the edge direction's x-sign flips (vertical edges skipped): while
    // the direction turns monotonically by a total of k full turns, it flips 2k times.
    const int s = sign(b.x - a.x);
    if (s != 0) {
      if (first_dx_sign == 0)
        first_dx_sign = s;
      else if (s != last_dx_sign)
        ++dx_sign_changes;
      last_dx_sign = s;
    }
  }
  if (turn == 0) return false;                           // every vertex straight: no area
  if (last_dx_sign != first_dx_sign) ++dx_sign_changes;  // close the cycle
  return dx_sign_changes == 2;
}

}  // namespace edgeland
