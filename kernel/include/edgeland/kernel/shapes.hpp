#pragma once
// Shape builders: the polygons a game carves and fills with (an explosion's circle, a digger's
// stroke, a crate's box), from integers only and valid by construction.
//
// GUARANTEES, for every argument in its range (any radius >= 1, any centre in the bound):
//   * VALID. The result passes validate(): a strictly convex, counter-clockwise polygon of at
//     least 3 vertices, every vertex within kCoordBound, starting at the lowest of its leftmost
//     vertices. Pass it on as PolygonSet{shape}.
//   * CLOSE. Each vertex is an ideal corner (a point on the circle, a corner of the box) rounded
//     to the nearest integer point, so the polygon is the ideal shape to within half a unit
//     diagonal (sqrt(2)/2) along its boundary; its area differs from the ideal one by at most
//     that times the perimeter (tests/kernel/shapes_test.cpp checks both).
//   * AT LEAST THE DIAMOND. The four points at distance 1 around each centre are always inside:
//     a shape of radius 1 is never thinner than that (a regular triangle of radius 1 grows to
//     hold them; every circle, capsule and box of radius or half extent >= 1 holds them anyway).
//   * CUT TO THE BOUND. Parts beyond kCoordBound are cut off; the cut rounds its new corners
//     toward the inside, so the result lies inside the ideal shape's cut (up to the rounding of
//     its own corners). Cut to nearly nothing (a centre on the bound's corner), the result is
//     the least triangle of the diamond inside the bound, (c, c +- (1, 0), c +- (0, 1)).
//   * DETERMINISTIC. Integer arithmetic only: points on circles come from a fixed-point sine and
//     cosine (Q62, a Taylor series in 128-bit integers: shape_trig.cpp) computed the same on
//     every platform; the same arguments give the same polygon everywhere. No formula leaves
//     its type (proofs/: shape_*_int128).
//
// HOW (why it is valid). The ideal corners are rounded, the diamond added, and the result is
// the convex hull of those points (Andrew's monotone chain, exact orientation): a hull of
// integer points not all on one line is a strictly convex counter-clockwise polygon. Each side
// of the bound's box then cuts it; a convex polygon cut by a line is convex, and its two new
// corners on the line are rounded toward the inside, so the cut stays inside the polygon. A last
// hull drops corners the rounding merged or made collinear.
//
// ERRORS. A centre or end beyond kCoordBound: CoordinateOutOfRange (operand kShape, `vertex`
// the argument's index, the message its name). A radius, half extent, side count or turn
// denominator outside its range: ArgumentOutOfRange naming it.
//
// COST. O(n log n) for n corners; no allocation beyond the result and a scratch array.
#include <cstdint>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

// An angle as a fraction of a full turn, counter-clockwise from +x: num / den turns (any num,
// 1 <= den <= kMaxTurnDenominator). {1, 4} is a quarter turn, {-1, 8} an eighth clockwise. A
// game with an angle in radians passes e.g. {round(angle / (2 pi) * 65536), 65536}.
struct Turn {
  std::int64_t num = 0;
  std::int64_t den = 1;
};

// The largest radius or half extent: 2^33, more than any distance within the bound's box, so a
// shape of this size from any centre covers all of it.
inline constexpr std::int64_t kMaxShapeRadius = std::int64_t{1} << 33;
inline constexpr std::int64_t kMaxShapeSides = std::int64_t{1} << 16;
inline constexpr std::int64_t kMaxTurnDenominator = std::int64_t{1} << 31;
// circle() uses at most this many sides.
inline constexpr std::int64_t kMaxCircleSides = 1024;

// The regular polygon with `sides` corners (3..kMaxShapeSides) at distance `radius`
// (1..kMaxShapeRadius) from `center`, the first at angle `phase`.
EDGELAND_EXPORT Polygon regular_polygon(Point64 center, std::int64_t radius, std::int64_t sides,
                                        Turn phase = {});

// The number of sides circle() gives a radius: the least multiple of 8 with sides^2 >= 10
// radius (the polygon then strays at most about half a unit from the circle: sagitta
// r (1 - cos(pi / n)) <= pi^2 r / (2 n^2) <= pi^2 / 20), from 8 up to kMaxCircleSides.
EDGELAND_EXPORT std::int64_t circle_sides(std::int64_t radius);

// A circle as the regular polygon of circle_sides(radius) sides, a corner on +x: symmetric in
// both axes and both diagonals.
EDGELAND_EXPORT Polygon circle(Point64 center, std::int64_t radius);

// A stroke from a to b of the given radius (a stadium: the segment widened by the radius, round
// ends), as the hull of circle()'s corners around both ends; a == b gives circle(a, radius).
EDGELAND_EXPORT Polygon capsule(Point64 a, Point64 b, std::int64_t radius);

// The axis-aligned box itself, counter-clockwise from box.min. Its corners must be in range and
// its width and height at least 1 (ArgumentOutOfRange "box width" / "box height" otherwise).
EDGELAND_EXPORT Polygon box_shape(const Box64& box);

// The box of half extents half_width (along the turned x axis) and half_height (1 ..
// kMaxShapeRadius each) around `center`, turned by `angle`.
EDGELAND_EXPORT Polygon rotated_box(Point64 center, std::int64_t half_width,
                                    std::int64_t half_height, Turn angle);

}  // namespace edgeland
