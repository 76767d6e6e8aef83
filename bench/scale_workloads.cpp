#include "scale_workloads.hpp"

#include <cmath>
#include <stdexcept>

#include "unit_draw.hpp"
#include "workloads.hpp"

namespace edgeland::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::int64_t kToothWidth = 40;
constexpr std::int64_t kGap = 40;
constexpr std::int64_t kPitch = kToothWidth + kGap;

// A star whose vertex i sits at angle 2*pi*i/n + turn and radius radius(i).
template <class RadiusFn>
Polygon star(std::size_t n, double cx, double cy, double turn, RadiusFn radius) {
  Polygon polygon;
  polygon.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(n) + turn;
    polygon.push_back(polar(cx, cy, radius(i), angle));
  }
  return polygon;
}

// Comb A shifted by (dx, dy), counter-clockwise: along the bottom, up the right end, then the
// teeth from right to left. Tooth 0's left edge runs straight down to the base corner, so no
// vertex is a straight angle.
Polygon comb(std::size_t teeth, std::int64_t tip, std::int64_t h, std::int64_t dx,
             std::int64_t dy) {
  const auto t = static_cast<std::int64_t>(teeth);
  Polygon polygon;
  polygon.reserve(4 * teeth + 2);
  polygon.push_back({dx, dy});
  polygon.push_back({dx + t * kPitch, dy});
  polygon.push_back({dx + t * kPitch, dy + h});
  for (std::int64_t k = t - 1; k >= 0; --k) {
    const std::int64_t left = dx + k * kPitch;
    polygon.push_back({left + kToothWidth, dy + h});
    polygon.push_back({left + kToothWidth, dy + tip});
    polygon.push_back({left, dy + tip});
    if (k > 0) polygon.push_back({left, dy + h});
  }
  return polygon;
}

}  // namespace

Operands combs(std::size_t teeth, std::int64_t tip, std::int64_t h) {
  if (2 * h >= tip) throw std::invalid_argument("combs: the base must be lower than tip/2");
  Operands out;
  out.subject = {comb(teeth, tip, h, 0, 0)};
  out.clip = {comb(teeth, tip, h, kToothWidth / 2, tip / 2)};
  require_valid(out.subject, "comb A");
  require_valid(out.clip, "comb B");
  return out;
}

Operands zigzag_stars(std::size_t n) {
  constexpr double kOuter = 1.0e8;
  constexpr double kInner = 0.9e8;
  const auto radius = [](std::size_t i) { return i % 2 == 0 ? kOuter : kInner; };
  Operands out;
  out.subject = {star(n, 0.0, 0.0, 0.0, radius)};
  out.clip = {star(n, 1234.0, -777.0, 2.0 * kPi * 3e-6, radius)};
  require_valid(out.subject, "zigzag star A");
  require_valid(out.clip, "zigzag star B");
  return out;
}

Operands star_minus_empty(std::size_t n) {
  SplitMix64 random(0x5CA1'E000 + n);
  Operands out;
  out.subject = {
      star(n, 0.0, 0.0, 0.0, [&](std::size_t) { return 5.0e7 * (1.0 + unit_draw(random)); })};
  require_valid(out.subject, "random star");
  return out;
}

}  // namespace edgeland::bench
