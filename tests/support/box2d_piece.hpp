#pragma once
// Convex pieces (convex_pieces.hpp) handed to Box2D 2.4's b2PolygonShape::Set, as a game's
// adapter would: coordinates relative to a nearby origin, times the metres of one unit, as
// float. Set welds vertices closer than b2_linearSlop / 2 and recomputes the hull by gift
// wrapping in float; these helpers say whether it kept the piece exactly.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::testing {

struct Box2dFrame {
  Point64 origin;                 // engine coordinates are taken relative to it
  double meters_per_unit = 0.01;  // at least b2_linearSlop (0.005 m): distinct points stay apart
};

// Whether Set keeps the piece: m_count equals its size and m_vertices are its vertices,
// converted, in the same cyclic order. Calls Set in this process: a piece that makes Debian's
// Box2D (built with assertions) fail b2Assert aborts the caller.
bool box2d_keeps(const Polygon& piece, const Box2dFrame& frame);

enum class Box2dVerdict : std::uint8_t { kKept, kAltered, kAborted };

// box2d_keeps for each piece, in child processes (batches, then one piece per child where a
// batch aborted), so an assertion in Set is reported as kAborted instead of ending the caller.
std::vector<Box2dVerdict> box2d_verdicts(const std::vector<Polygon>& pieces,
                                         const std::vector<Box2dFrame>& frames);

// Pieces whose corners turn as little as a lattice allows (orient 1), of extent about `extent`:
//   kSliver      the triangle 0, d, 2d + e, of area 1/2;
//   kKinkedQuad  that corner and an apex left of its chord;
//   kArc         7 edges d_k = d + k e (every corner orient 1) closed by the chord;
// where d = (extent / 2, offset) (extent / 7 for the arc; swapped when `transpose`) and e is the
// least lattice turn of d (cross(d, e) = 1). Empty when d is not primitive or the piece would
// not be strictly convex.
enum class LeastTurnKind : std::uint8_t { kSliver, kKinkedQuad, kArc };
Polygon least_turn_piece(LeastTurnKind kind, std::int64_t extent, std::int64_t offset,
                         bool transpose);

// The piece moved so that its box's upper corner is (reach, reach), then turned by
// `quarter_turns` quarter turns about the origin: its reach is then `reach`.
Polygon placed(Polygon piece, std::int64_t reach, int quarter_turns);

// The largest |coordinate| of the piece relative to `origin`, and its diameter in the max
// norm (the larger side of its bounding box): what Set's float rounding depends on.
std::int64_t reach(const Polygon& piece, Point64 origin);
std::int64_t extent(const Polygon& piece);

}  // namespace edgeland::testing
