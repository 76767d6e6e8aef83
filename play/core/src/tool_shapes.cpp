#include "edgeland/play/tool_shapes.hpp"

#include <algorithm>

#include "demo_shapes.hpp"
#include "integer_trig.hpp"

namespace edgeland::play {

int heading(std::int64_t dx, std::int64_t dy) noexcept {
  int best = 0;
  Int128 best_dot = 0;
  for (int a = 0; a < cli::kFullTurn; ++a) {
    const Int128 dot = Int128{dx} * cli::cosine(a) + Int128{dy} * cli::sine(a);
    if (a == 0 || dot > best_dot) {
      best = a;
      best_dot = dot;
    }
  }
  return best;
}

Ring circle_ring(Point64 c, std::int64_t r) {
  constexpr int kCorners = 24;
  Ring ring;
  for (int k = 0; k < kCorners; ++k)
    ring.push_back(cli::polar(c, r, k * cli::kFullTurn / kCorners));
  return ring;
}

Ring tool_ring(const ToolEdit& edit) {
  const std::int64_t r = std::clamp(edit.radius, kMinToolRadius, kMaxToolRadius);
  if (edit.from == edit.to) return circle_ring(edit.to, r);
  const int angle = heading(edit.to.x - edit.from.x, edit.to.y - edit.from.y);
  return cli::demo::capsule(edit.from, edit.to, angle, r);
}

log::LandscapeEditKind edit_kind(ToolKind tool) noexcept {
  switch (tool) {
    case ToolKind::kExplosion:
    case ToolKind::kDigger:
      return log::LandscapeEditKind::kCarve;
    case ToolKind::kFill:
      return log::LandscapeEditKind::kFill;
    case ToolKind::kWater:
      return log::LandscapeEditKind::kFillEmpty;
    case ToolKind::kReplace:
      return log::LandscapeEditKind::kReplace;
  }
  return log::LandscapeEditKind::kCarve;
}

}  // namespace edgeland::play
