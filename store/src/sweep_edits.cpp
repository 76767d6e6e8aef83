#include "edgeland/store/sweep_edits.hpp"

#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::store {
namespace {

constexpr std::int64_t kSpacing = 128;

}  // namespace

SweepEdits::SweepEdits(std::int64_t side, int region_depth, std::int64_t sides)
    : side_(side),
      per_region_side_(side / (std::int64_t{1} << region_depth) / kSpacing),
      regions_side_(std::int64_t{1} << region_depth),
      depth_(region_depth),
      sides_(sides),
      slots_(static_cast<std::size_t>(per_region_side_ * per_region_side_ * regions_side_ *
                                      regions_side_)) {}

LandscapeConfig SweepEdits::config() const {
  LandscapeConfig c;
  c.region_depth = depth_;
  c.region_ids = true;
  return c;
}

// Slot k: region k / per-region slots (row by row), then its place in the region (row by row).
Point64 SweepEdits::slot(std::size_t k) const {
  const auto per = static_cast<std::size_t>(per_region_side_ * per_region_side_);
  const auto region = static_cast<std::int64_t>(k / per), in = static_cast<std::int64_t>(k % per);
  const std::int64_t rx = region % regions_side_, ry = region / regions_side_;
  const std::int64_t region_side = side_ / regions_side_;
  return {rx * region_side + (in % per_region_side_) * kSpacing + kSpacing / 2,
          ry * region_side + (in / per_region_side_) * kSpacing + kSpacing / 2};
}

Edit SweepEdits::at(std::size_t i) const {
  const std::uint64_t r = mix64(i + 0x5EED);
  if (i < slots_) {
    const std::int64_t radius = 40 + static_cast<std::int64_t>(r % 20);
    return Edit::fill(ValidSet(PolygonSet{regular_polygon(slot(i), radius, sides_)}),
                      static_cast<std::uint8_t>(1 + r % 3));
  }
  const Point64 from = slot((i - slots_) * 4);
  const Point64 to{std::min(side_ - 20, from.x + 150),
                   std::min(side_ - 20, from.y + 40 + static_cast<std::int64_t>(r % 60))};
  return Edit::carve(
      ValidSet(PolygonSet{capsule(from, to, 10 + static_cast<std::int64_t>(r % 8))}));
}

}  // namespace edgeland::store
