#pragma once
// The clipper's value types (clip.hpp is the front end): the operation, the fill rule, the
// options, the statistics and the result of an operation on polygon sets.
#include <cstddef>
#include <cstdint>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

enum class ClipOp : std::uint8_t { kUnion, kIntersection, kDifference, kXor };
// How arbitrary rings are filled by normalize(): a point is inside when its winding number w
// satisfies: odd (kEvenOdd), w != 0 (kNonZero), w > 0 (kPositive), w < 0 (kNegative).
enum class FillRule : std::uint8_t { kEvenOdd, kNonZero, kPositive, kNegative };

EDGELAND_EXPORT const char* op_name(ClipOp op) noexcept;
EDGELAND_EXPORT const char* fill_rule_name(FillRule rule) noexcept;

struct ClipOptions {
  // Check every stage's result and re-validate every output (on in tests, fuzzers, `--check`).
  bool checked = false;
};

struct ClipStats {
  std::size_t intersections = 0;      // edge pairs meeting other than at shared vertices
  std::size_t vertices_snapped = 0;   // points moved to the grid by snap rounding
  std::size_t holes_split = 0;        // holes removed by cutting their polygon
  std::size_t zero_area_dropped = 0;  // collapsed pieces removed
};

struct ClipResult {
  PolygonSet polygons;
  ClipStats stats;
};

}  // namespace edgeland
