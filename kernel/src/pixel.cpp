#include "edgeland/kernel/pixel.hpp"

#include <algorithm>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

// A parameter value t = num / den along the segment, den > 0.
struct Param {
  Int128 num;
  Int128 den;
};

// a < b for fractions with positive denominators (|num|, den < 2^35: products < 2^70).
bool less(const Param& a, const Param& b) { return a.num * b.den < b.num * a.den; }

// pixel_line_slack: >= 0 when the closed pixel of c reaches the line of s (formulas.hpp).
Int128 normal_slack(const Segment& s, Point64 c) noexcept {
  return formulas::pixel_line_slack<arith::Checked<std::int64_t>, W>(s.a.x, s.a.y, s.b.x, s.b.y,
                                                                     c.x, c.y)
      .v;
}

}  // namespace

bool segment_meets_closed_pixel(const Segment& s, Point64 c) noexcept {
  // Along x the closed pixel is [c.x - 1/2, c.x + 1/2], which holds one integer: an integer
  // segment's x-range meets it exactly when it contains c.x. Likewise along y.
  if (!segment_box(s).contains(c)) return false;
  return normal_slack(s, c) >= 0;
}

bool segment_meets_pixel(const Segment& s, Point64 c) noexcept {
  // Quick rejection by separating axes of the closed pixel (half-width 1/2) and the segment: its
  // box, then its normal. Callers ask mostly about pixels near, not on, the segment; the exact
  // clipping below costs several times more.
  if (!segment_meets_closed_pixel(s, c)) return false;
  // The same three axes with strict inequalities: the segment meets the open square, hence
  // the half-open pixel. (Were it apart from the open square, some line would separate them,
  // and the separating directions form an angular interval whose ends are edge normals of
  // the square or of the segment, which are these axes; at such an end the projections meet
  // at most at an end of the square's open interval.) The common case of a segment running
  // through the pixel is answered here, without the exact clipping.
  if (2 * std::min(s.a.x, s.b.x) < 2 * c.x + 1 && 2 * std::max(s.a.x, s.b.x) > 2 * c.x - 1 &&
      2 * std::min(s.a.y, s.b.y) < 2 * c.y + 1 && 2 * std::max(s.a.y, s.b.y) > 2 * c.y - 1 &&
      normal_slack(s, c) > 0)
    return true;
  // Doubled coordinates relative to the pixel centre: the pixel is [-1, 1) x [-1, 1).
  const Int128 px = 2 * Int128(s.a.x - c.x), py = 2 * Int128(s.a.y - c.y);
  const Int128 dx = 2 * Int128(s.b.x - s.a.x), dy = 2 * Int128(s.b.y - s.a.y);
  // Liang-Barsky against the closed square: each constraint reads p * t <= q.
  Param lo{0, 1}, hi{1, 1};
  const Int128 ps[4] = {-dx, dx, -dy, dy};
  const Int128 qs[4] = {px + 1, 1 - px, py + 1, 1 - py};
  for (int i = 0; i < 4; ++i) {
    const Int128 p = ps[i], q = qs[i];
    if (p == 0) {
      if (q < 0) return false;
      continue;
    }
    const Param r = p > 0 ? Param{q, p} : Param{-q, -p};
    if (p < 0) {
      if (less(lo, r)) lo = r;
    } else {
      if (less(r, hi)) hi = r;
    }
  }
  if (less(hi, lo)) return false;
  // The closed square is met on [lo, hi]. Remove what lies only on the open top/right sides.
  if (!less(lo, hi)) {                               // a single point: it must have x < 1 and y < 1
    const Int128 x_den = px * lo.den + lo.num * dx;  // x * den
    const Int128 y_den = py * lo.den + lo.num * dy;
    return x_den < lo.den && y_den < lo.den;
  }
  // A piece of positive length lies on the right side only when vertical at x = 1, on the top
  // side only when horizontal at y = 1; otherwise it has points inside the half-open square.
  if (dx == 0 && px == 1) return false;
  if (dy == 0 && py == 1) return false;
  return true;
}

Int128 projection(const Segment& s, Point64 p) noexcept {
  return formulas::dot_widening<arith::Checked<std::int64_t>, W>(s.a.x, s.a.y, s.b.x, s.b.y, p.x,
                                                                 p.y)
      .v;
}

}  // namespace edgeland
