#pragma once
// The shapes of the front ends' tools (play/web, play/desktop), in integers: a tool pressed at
// one point is a circle (a regular polygon) around it, a tool dragged from one point to the next
// is the stadium around that stroke. Integer trigonometry (cli/integer_trig.hpp) makes the same
// input give the same vertices in the browser and on the desktop, so a recorded session replays
// to the same world anywhere.
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

// The direction of (dx, dy) in 1/256 turns (integer_trig.hpp's unit): the table angle whose
// unit vector has the largest dot product with it (0 for the zero vector).
int heading(std::int64_t dx, std::int64_t dy) noexcept;

// The regular 24-gon of radius r around c, counter-clockwise.
Ring circle_ring(Point64 c, std::int64_t r);

// The tool's shape: circle_ring(to, r) for a click, the stadium around from -> to otherwise
// (demo_shapes.hpp capsule). The radius is clamped to [kMinToolRadius, kMaxToolRadius].
Ring tool_ring(const ToolEdit& edit);

// The landscape edit a tool makes (landscape_log.hpp's kinds): carve, fill, fill_empty, replace.
log::LandscapeEditKind edit_kind(ToolKind tool) noexcept;

}  // namespace edgeland::play
