#pragma once
// Stage 1 of the surface (game/README.md): where the boundary of a cell's solid polygons lies.
// Each edge of a solid polygon is cut into pieces that lie
//   * on another solid polygon of the cell, edge against edge in opposite directions: a CONTACT
//     (the two polygons are one piece of solid there; nothing to export);
//   * on one of the cell's sides: a PORT (what lies across depends on the neighbour cell);
//   * elsewhere: FREE, which is surface (non-solid on the right).
// Exact: pieces end at polygon vertices only (supporting_line.hpp groups collinear edges).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "edgeland/game/physics_materials.hpp"
#include "edgeland/kernel/supporting_line.hpp"

namespace edgeland::game_detail {

// One polygon of a cell as stage 1 reads it.
struct CellPolygon {
  Material material = kEmpty;
  const Polygon* ring = nullptr;
};

// A piece of a solid polygon's boundary, directed with the polygon on its left.
struct BoundaryPiece {
  Point64 a, b;
  std::uint32_t polygon = 0;  // index in the cell's polygons
};

// The sides of a box in counter-clockwise order. A solid polygon's edge on a side runs along the
// box counter-clockwise: +x on the bottom, +y on the right, -x on the top, -y on the left.
enum class Side : std::uint8_t { kBottom, kRight, kTop, kLeft };
inline constexpr std::array<Side, 4> kSides{Side::kBottom, Side::kRight, Side::kTop, Side::kLeft};

struct SolidBoundary {
  std::vector<BoundaryPiece> free;
  std::array<std::vector<BoundaryPiece>, 4> ports;     // per Side, in counter-clockwise order
  std::vector<std::array<std::uint32_t, 2>> contacts;  // polygon pairs, lower index first, unique
};

// An edge not on a side of the box, as an interval of its supporting line.
struct LineEdge {
  SupportingLine line;
  bool forward = true;          // runs in the line's direction
  std::int64_t lo = 0, hi = 0;  // positions along the line, lo < hi
  Point64 lo_point, hi_point;
  std::uint32_t polygon = 0;
};

// Stage 1 into `out` (its vectors' storage reused), with `edges` as scratch. O(n log n) for n
// edges of the cell's solid polygons.
void solid_boundary(const Box64& box, std::span<const CellPolygon> polygons,
                    const PhysicsMaterials& materials, SolidBoundary& out,
                    std::vector<LineEdge>& edges);

// How many times solid_boundary() ran in this process (a counter for the tests that check one
// pass per changed cell).
std::uint64_t solid_boundary_runs();

// The side of `box` the segment a -> b lies on (both ends on one side line), if any.
std::optional<Side> side_of(const Box64& box, Point64 a, Point64 b);

// The coordinate that runs along a side (x on the bottom and top, y on the right and left).
std::int64_t along(Side side, Point64 p);
// The point of the side's line at coordinate `t` along it.
Point64 point_on(const Box64& box, Side side, std::int64_t t);
// The side facing it (bottom and top, right and left).
Side opposite(Side side);
// Whether `other` lies across `side` of `box`: its opposite side on the same line (whether they
// share a stretch of positive length is the caller's to check).
bool across(const Box64& box, Side side, const Box64& other);
// Whether `side` of `inner` lies on the same side's line of `outer` (a cell on the world's border,
// a child on its node's side).
bool on_side_of(const Box64& inner, Side side, const Box64& outer);

}  // namespace edgeland::game_detail
