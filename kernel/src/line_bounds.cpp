#include "edgeland/kernel/line_bounds.hpp"

#include <utility>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

}  // namespace

IntegerRange line_y_at(Point64 a, Point64 b, std::int64_t x) {
  if (a.x > b.x) std::swap(a, b);
  // y = a.y + num / den with den = b.x - a.x > 0: the crossing formula of shape_cut.cpp, whose
  // rounding either way fits Int128 (theorem shape_cut_int128, points within 2^35).
  const W num = formulas::crossing_numerator<W>(x, a.x, a.y, b.y), den = W(b.x) - W(a.x);
  const W lo = W(a.y) + floor_div(num, den), hi = W(a.y) - floor_div(-num, den);
  return {static_cast<std::int64_t>(lo.v), static_cast<std::int64_t>(hi.v)};
}

IntegerRange line_x_at(Point64 a, Point64 b, std::int64_t y) {
  return line_y_at({a.y, a.x}, {b.y, b.x}, y);
}

}  // namespace edgeland
