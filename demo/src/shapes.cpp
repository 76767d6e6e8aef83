#include "edgeland/demo/shapes.hpp"

#include <algorithm>

#include "edgeland/demo/integer_trig.hpp"

namespace edgeland::demo {
namespace {

// The line's sample points x0, x0 + step, ..., x1 (the last one always x1).
std::vector<std::int64_t> sample_xs(const Box64& world, std::int64_t step) {
  std::vector<std::int64_t> xs;
  for (std::int64_t x = world.min.x; x < world.max.x; x += step) xs.push_back(x);
  xs.push_back(world.max.x);
  return xs;
}

}  // namespace

Ring rough_ngon(Point64 c, std::int64_t r, int n, int roughness, SplitMix64& random) {
  Ring ring;
  const int phase = static_cast<int>(random.between(0, kFullTurn - 1));
  for (int i = 0; i < n; ++i) {
    const std::int64_t radius = r * random.between(100 - roughness, 100) / 100;
    ring.push_back(polar(c, radius, phase + i * kFullTurn / n));
  }
  return ring;
}

std::int64_t WavyLine::y_at(std::int64_t x, const Box64& world) const {
  const std::int64_t width = world.max.x - world.min.x;
  std::int64_t y = base;
  for (std::size_t i = 0; i < amplitude.size(); ++i) {
    const std::int64_t turns = cycles[i] * kFullTurn * (x - world.min.x) / width;
    y += unscale(amplitude[i] * sine(static_cast<int>(turns % kFullTurn) + phase[i]));
  }
  return y;
}

WavyLine random_wavy_line(std::int64_t base, std::int64_t amplitude, SplitMix64& random) {
  WavyLine line;
  line.base = base;
  int cycles = static_cast<int>(random.between(1, 3));
  for (std::size_t i = 0; i < line.amplitude.size(); ++i) {
    line.amplitude[i] = amplitude;
    line.cycles[i] = cycles;
    line.phase[i] = static_cast<int>(random.between(0, kFullTurn - 1));
    amplitude /= 2;
    cycles = cycles * 2 + static_cast<int>(random.between(1, 3));
  }
  return line;
}

Ring region_below(const WavyLine& line, const Box64& world, std::int64_t step) {
  const std::int64_t bottom = world.min.y - 16;
  Ring ring{{world.min.x, bottom}, {world.max.x, bottom}};
  const std::vector<std::int64_t> xs = sample_xs(world, step);
  for (auto x = xs.rbegin(); x != xs.rend(); ++x) {
    ring.push_back({*x, std::max(line.y_at(*x, world), bottom + 1)});
  }
  return ring;
}

Ring band_along(const WavyLine& line, std::int64_t offset, std::int64_t thickness,
                const Box64& world, std::int64_t step) {
  const std::vector<std::int64_t> xs = sample_xs(world, step);
  Ring ring;
  for (const std::int64_t x : xs) ring.push_back({x, line.y_at(x, world) + offset});
  for (auto x = xs.rbegin(); x != xs.rend(); ++x) {
    ring.push_back({*x, line.y_at(*x, world) + offset + thickness});
  }
  return ring;
}

}  // namespace edgeland::demo
