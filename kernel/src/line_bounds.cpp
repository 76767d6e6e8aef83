#include "edgeland/kernel/line_bounds.hpp"

#include <utility>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

}  // namespace

IntegerRange line_y_at(Point64 a, Point64 b, std::int64_t x) {
  // Exact without dividing: a flat line, and the ends (grid cells ask at many of them).
  if (a.y == b.y || x == a.x) return {a.y, a.y};
  if (x == b.x) return {b.y, b.y};
  if (a.x > b.x) std::swap(a, b);
  // y = a.y + num / den with den = b.x - a.x > 0: the crossing formula of shape_cut.cpp, whose
  // rounding either way fits Int128 (theorem shape_cut_int128, points within 2^35).
  const W num = formulas::crossing_numerator<W>(x, a.x, a.y, b.y), den = W(b.x) - W(a.x);
  // One division: the value lies in [floor, floor + 1] (the ceiling would take a second).
  const W lo = W(a.y) + floor_div(num, den);
  return {static_cast<std::int64_t>(lo.v), static_cast<std::int64_t>(lo.v) + 1};
}

IntegerRange line_x_at(Point64 a, Point64 b, std::int64_t y) {
  return line_y_at({a.y, a.x}, {b.y, b.x}, y);
}

}  // namespace edgeland
