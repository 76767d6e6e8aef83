// first_clockwise: walk the eight slots clockwise from the slot of `from`; within an open
// quadrant the first direction met is the most counter-clockwise one (an orientation test).
#include "edgeland/kernel/around_vertex.hpp"

#include <vector>

#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland {
namespace {

// d1 lies counter-clockwise of d2 (both in one open quadrant, or d2 on its bounding rays).
bool ccw_of(Point64 d1, Point64 d2) {
  return orientation({0, 0}, d2, d1) == Orientation::kCounterClockwise;
}

// Among the directions in `slot` that `accept` admits, the one a clockwise sweep meets first:
// the most counter-clockwise one.
template <class Accept>
std::optional<std::size_t> first_in_slot(std::span<const Point64> dirs, int slot, Accept accept) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    if (direction_slot(dirs[i]) != slot || !accept(dirs[i])) continue;
    if (!best || ccw_of(dirs[i], dirs[*best])) best = i;
  }
  return best;
}

Point64 mirrored(Point64 d) { return {d.x, -d.y}; }

}  // namespace

int direction_slot(Point64 d) noexcept {
  if (d.y == 0) return d.x > 0 ? 0 : 4;
  if (d.x == 0) return d.y > 0 ? 2 : 6;
  if (d.y > 0) return d.x > 0 ? 1 : 3;
  return d.x < 0 ? 5 : 7;
}

std::optional<std::size_t> first_clockwise(Point64 from, std::span<const Point64> dirs,
                                           const BlockedQuadrants& blocked) {
  const int start = direction_slot(from);
  const auto all = [](Point64) { return true; };
  // Still in the slot of `from`: the directions clockwise of it.
  if (start % 2 == 1)
    if (auto i = first_in_slot(dirs, start, [&](Point64 d) { return ccw_of(from, d); })) return i;
  for (int step = 1; step < 8; ++step) {
    const int slot = (start - step + 8) % 8;
    if (slot % 2 == 1 && blocked[static_cast<std::size_t>(slot / 2)]) return std::nullopt;
    if (auto i = first_in_slot(dirs, slot, all)) return i;
  }
  // Back in the slot of `from` after a full turn: what is counter-clockwise of it, then `from`
  // itself.
  if (start % 2 == 1)
    if (auto i = first_in_slot(dirs, start, [&](Point64 d) { return !ccw_of(from, d); })) return i;
  return first_in_slot(dirs, start, all);
}

std::optional<std::size_t> first_counterclockwise(Point64 from, std::span<const Point64> dirs,
                                                  const BlockedQuadrants& blocked) {
  // Mirrored in the x axis a counter-clockwise sweep is a clockwise one; quadrant q becomes 3 - q.
  detail::ScratchVector<Point64> mirror;
  mirror.resize(dirs.size());
  for (std::size_t i = 0; i < dirs.size(); ++i) mirror[i] = mirrored(dirs[i]);
  const BlockedQuadrants flipped{blocked[3], blocked[2], blocked[1], blocked[0]};
  return first_clockwise(mirrored(from), mirror, flipped);
}

}  // namespace edgeland
