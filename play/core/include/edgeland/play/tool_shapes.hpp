#pragma once
// The shapes of the front ends' tools (play/web, play/desktop), in integers: a tool pressed at
// one point is a circle (a regular polygon) around it, a tool dragged from one point to the next
// is the stadium around that stroke, both the kernel's shape builders (kernel/shapes.hpp), whose
// integer trigonometry makes the same input give the same vertices in the browser and on the
// desktop, so a recorded session replays to the same world anywhere.
#include <cstdint>

#include "edgeland/io/landscape_log.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::play {

// What a tool does to the material under its shape.
enum class ToolKind : std::uint8_t {
  kExplosion,  // carve
  kDigger,     // carve (dragged)
  kFill,       // fill with `material`
  kWater,      // fill_empty with `material` (water by default): only empty space fills
  kReplace,    // replace `from` by `material`
};

// One use of a tool: the stroke from -> to (a click has from == to) of the given radius.
struct ToolEdit {
  ToolKind tool = ToolKind::kExplosion;
  Point64 from, to;
  std::int64_t radius = 32;  // world units, at least kMinToolRadius
  Material material = kEmpty;
  Material from_material = kEmpty;  // kReplace only
};

inline constexpr std::int64_t kMinToolRadius = 2;
inline constexpr std::int64_t kMaxToolRadius = 1 << 20;  // |points| stay far inside the bound

// The corners of a click's shape.
inline constexpr std::int64_t kToolCorners = 24;

// The tool's shape, valid by construction: the kernel's regular_polygon(to, r, kToolCorners) for
// a click, its capsule(from, to, r) otherwise. The radius is clamped to [kMinToolRadius,
// kMaxToolRadius].
Polygon tool_shape(const ToolEdit& edit);

// The landscape edit a tool makes (landscape_log.hpp's kinds): carve, fill, fill_empty, replace.
log::LandscapeEditKind edit_kind(ToolKind tool) noexcept;

}  // namespace edgeland::play
