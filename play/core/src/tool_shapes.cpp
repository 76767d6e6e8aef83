#include "edgeland/play/tool_shapes.hpp"

#include <algorithm>

#include "edgeland/kernel/shapes.hpp"

namespace edgeland::play {

Polygon tool_shape(const ToolEdit& edit) {
  const std::int64_t r = std::clamp(edit.radius, kMinToolRadius, kMaxToolRadius);
  if (edit.from == edit.to) return regular_polygon(edit.to, r, kToolCorners);
  return capsule(edit.from, edit.to, r);
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
