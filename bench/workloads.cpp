#include "workloads.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "edgeland/kernel/validate.hpp"
#include "unit_draw.hpp"

namespace edgeland::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStarRadius = 1.0e7;

using Random = SplitMix64;

// A star polygon: vertex i at angle 2*pi*(i + offset)/n and radius radius(i, angle).
template <class RadiusFn>
Polygon star(std::size_t n, double cx, double cy, double offset, RadiusFn radius) {
  Polygon polygon;
  polygon.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * (static_cast<double>(i) + offset) / static_cast<double>(n);
    polygon.push_back(polar(cx, cy, radius(angle), angle));
  }
  return polygon;
}

Polygon smooth_star(std::size_t n, double cx, double cy, double offset, Random& random) {
  const double phase3 = 2.0 * kPi * unit_draw(random);
  const double phase7 = 2.0 * kPi * unit_draw(random);
  return star(n, cx, cy, offset, [&](double angle) {
    return kStarRadius *
           (0.75 + 0.15 * std::sin(3.0 * angle + phase3) + 0.05 * std::sin(7.0 * angle + phase7));
  });
}

Polygon spiky_star(std::size_t n, double cx, double cy, double offset, Random& random) {
  return star(n, cx, cy, offset,
              [&](double) { return kStarRadius * (0.3 + 0.7 * unit_draw(random)); });
}

}  // namespace

Point64 polar(double cx, double cy, double r, double angle) {
  return {std::llround(cx + r * std::cos(angle)), std::llround(cy + r * std::sin(angle))};
}

void require_valid(const PolygonSet& set, const char* what) {
  const ValidationReport report = validate(set, 1);
  if (!report.ok()) {
    throw std::logic_error(std::string("bench input ") + what +
                           " is invalid: " + report.violations.front().describe());
  }
}

Operands smooth_stars(std::size_t n) {
  Random random(0x5A00'7000 + n);
  Operands out;
  out.subject = {smooth_star(n, 0.0, 0.0, 0.0, random)};
  out.clip = {smooth_star(n, 0.11 * kStarRadius, 0.07 * kStarRadius, 0.5, random)};
  require_valid(out.subject, "smooth star (subject)");
  require_valid(out.clip, "smooth star (clip)");
  return out;
}

Operands spiky_stars(std::size_t n) {
  Random random(0x5B1C'E000 + n);
  Operands out;
  out.subject = {spiky_star(n, 0.0, 0.0, 0.0, random)};
  out.clip = {spiky_star(n, 0.12 * kStarRadius, 0.09 * kStarRadius, 0.5, random)};
  require_valid(out.subject, "spiky star (subject)");
  require_valid(out.clip, "spiky star (clip)");
  return out;
}

Operands checkerboard(std::size_t n) {
  constexpr std::int64_t kSide = 1000;
  // Enough columns for n black cells in a square-ish board.
  std::int64_t columns = 1;
  while (static_cast<std::size_t>(columns * columns) < 2 * n) ++columns;
  auto square = [](std::int64_t x, std::int64_t y) {
    return Polygon{{x, y}, {x + kSide, y}, {x + kSide, y + kSide}, {x, y + kSide}};
  };
  Operands out;
  for (std::int64_t row = 0; out.subject.size() < n; ++row) {
    for (std::int64_t col = 0; col < columns && out.subject.size() < n; ++col) {
      if ((row + col) % 2 != 0) continue;
      out.subject.push_back(square(col * kSide, row * kSide));
      out.clip.push_back(square(col * kSide + kSide / 2, row * kSide + kSide / 4));
    }
  }
  require_valid(out.subject, "checkerboard (subject)");
  require_valid(out.clip, "checkerboard (clip)");
  return out;
}

Carving carving(std::size_t count) {
  constexpr std::int64_t kSize = 8192;
  constexpr double kRadius = 40.0;
  constexpr std::size_t kSides = 32;
  Random random(0xCA4'F1A6);
  Carving out;
  out.square = {{0, 0}, {kSize, 0}, {kSize, kSize}, {0, kSize}};
  out.holes.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto cx = static_cast<double>(random.next() % (kSize + 1));
    const auto cy = static_cast<double>(random.next() % (kSize + 1));
    out.holes.push_back(star(kSides, cx, cy, 0.0, [&](double) { return kRadius; }));
    require_valid({out.holes.back()}, "carving 32-gon");
  }
  return out;
}

}  // namespace edgeland::bench
