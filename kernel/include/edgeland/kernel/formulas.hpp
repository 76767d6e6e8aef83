#pragma once
// The kernel's arithmetic, written once over a number type `W`.
//
// NOT API: installed only because the public inline predicates (predicates.hpp) are written
// with these templates; edgeland::formulas may change without notice. Do not include it
// yourself.
//
// The library instantiates these with arith::Checked<Int128>; proofs/ instantiates the very
// same templates with a Z3-backed symbolic integer that asks, at every operation, whether the
// exact value can leave the range of the machine type. Keep them branch-free: a formula that
// needs a case split takes it as a separate function so each case can be proven on its own.
// Inputs are coordinates already checked against kCoordBound (point.hpp).

namespace edgeland::formulas {

// Cross product of (ax, ay) and (bx, by).
template <class W>
constexpr W cross(W ax, W ay, W bx, W by) {
  return ax * by - ay * bx;
}

// The offset of the line through p with direction (dx, dy): cross(d, p), equal for every point
// of the line (supporting_line.hpp). d is a coordinate difference reduced by its gcd, so |d|
// stays within 2 kCoordBound per component (theorem line_offset_int128).
template <class W>
constexpr W line_offset(W dx, W dy, W px, W py) {
  return cross(dx, dy, px, py);
}

// Twice the signed area of triangle abc: > 0 when c is left of a->b.
template <class W>
constexpr W orient(W ax, W ay, W bx, W by, W cx, W cy) {
  return cross(bx - ax, by - ay, cx - ax, cy - ay);
}

// orient() in two number types: the coordinate differences in D, the products and their
// difference in W (constructible from D). With D = 64-bit (differences of in-range coordinates
// fit it: theorem orient_differences_int64) each product is one widening 64 x 64 -> 128-bit
// multiply, about three times faster than orient() computed wholly in 128 bits; the value is
// the same (theorem orient_widening_int128 bounds the products and the result).
template <class D>
struct OrientDifferences {
  D bx, by, cx, cy;  // b - a and c - a
};

template <class D>
constexpr OrientDifferences<D> orient_differences(D ax, D ay, D bx, D by, D cx, D cy) {
  return {bx - ax, by - ay, cx - ax, cy - ay};
}

template <class D, class W>
constexpr W orient_widening(D ax, D ay, D bx, D by, D cx, D cy) {
  const OrientDifferences<D> d = orient_differences(ax, ay, bx, by, cx, cy);
  return cross(W(d.bx), W(d.by), W(d.cx), W(d.cy));
}

// Dot product of (b - a) and (c - a): sign tells whether c projects before, onto or past a.
template <class W>
constexpr W dot_from(W ax, W ay, W bx, W by, W cx, W cy) {
  return (bx - ax) * (cx - ax) + (by - ay) * (cy - ay);
}

// dot_from() with the differences in D and the products in W, as orient_widening (theorems
// orient_differences_int64 for the differences, dot_widening_int128 for the rest).
template <class D, class W>
constexpr W dot_widening(D ax, D ay, D bx, D by, D cx, D cy) {
  const OrientDifferences<D> d = orient_differences(ax, ay, bx, by, cx, cy);
  return W(d.bx) * W(d.cx) + W(d.by) * W(d.cy);
}

// Exact intersection of the lines through segments p0->p1 and q0->q1 as homogeneous
// coordinates (x_num / den, y_num / den). den == 0 means parallel lines.
template <class W>
struct Homogeneous {
  W x_num, y_num, den;
};

template <class W>
constexpr Homogeneous<W> line_intersection(W p0x, W p0y, W p1x, W p1y, W q0x, W q0y, W q1x, W q1y) {
  const W rx = p1x - p0x, ry = p1y - p0y;
  const W sx = q1x - q0x, sy = q1y - q0y;
  const W den = cross(rx, ry, sx, sy);
  const W t = cross(q0x - p0x, q0y - p0y, sx, sy);
  return {p0x * den + rx * t, p0y * den + ry * t, den};
}

// The one rounding rule of the library: the nearest integer, halves rounded up (toward +inf),
// i.e. floor(num / den + 1/2) = floor((2 num + den) / (2 den)), for den > 0.
template <class W>
constexpr W round_half_up(W num, W den) {
  const W two = W(2);
  return floor_div(two * num + den, two * den);
}

// --- Rays (ray.hpp): the ray o + t d, t >= 0, with |d| components up to kMaxRayDirection ---

// The ray against the line through edge p -> q. With den = cross(d, q - p) != 0 the lines meet
// at t = t_num / den along the ray and u = u_num / den along the edge (u in [0, 1] on it).
template <class W>
struct RayEdge {
  W t_num, u_num, den;
};

template <class W>
constexpr RayEdge<W> ray_edge(W ox, W oy, W dx, W dy, W px, W py, W qx, W qy) {
  return {orient(ox, oy, px, py, qx, qy),  // == cross(p - o, q - p)
          cross(px - ox, py - oy, dx, dy), cross(dx, dy, qx - px, qy - py)};
}

// The parameter of point p projected on the ray's line, times dot(d, d): orders points along
// the ray (a ray along an edge meets it at its nearer end).
template <class W>
constexpr W ray_projection(W ox, W oy, W dx, W dy, W px, W py) {
  return (px - ox) * dx + (py - oy) * dy;
}

// dot(d, d): the denominator of ray_projection's parameter.
template <class W>
constexpr W squared_length(W dx, W dy) {
  return dx * dx + dy * dy;
}

// The point o + (t_num / den) d as homogeneous coordinates over den.
template <class W>
constexpr Homogeneous<W> ray_point(W ox, W oy, W dx, W dy, W t_num, W den) {
  return {ox * den + t_num * dx, oy * den + t_num * dy, den};
}

// --- Exact points ---

// c * den: an integer coordinate c scaled to a homogeneous point's denominator, to test whether
// that point is exactly c (x_num == c * den) without dividing.
template <class W>
constexpr W scaled(W c, W den) {
  return c * den;
}

// --- Pixels (pixel.hpp) ---

// |bx - ax| + |by - ay|, in the differences' type D (below 2^33 for in-range points).
// `magnitude` (the absolute value) is found by ADL.
template <class D>
constexpr D taxicab_length(D ax, D ay, D bx, D by) {
  return magnitude(bx - ax) + magnitude(by - ay);
}

// Separating axis along the normal of segment a -> b: the closed unit square centred at c
// reaches the segment's line exactly when the result is >= 0, i.e. 2 |orient(a, b, c)| <=
// |bx - ax| + |by - ay| (along the normal the square reaches (|dx| + |dy|) / 2). Differences in
// D, products in W, as orient_widening.
template <class D, class W>
constexpr W pixel_line_slack(D ax, D ay, D bx, D by, D cx, D cy) {
  const W det = orient_widening<D, W>(ax, ay, bx, by, cx, cy);
  return W(taxicab_length<D>(ax, ay, bx, by)) - W(2) * magnitude(det);
}

// --- Edge normals (edge_normal.hpp) ---

// The outward normal of edge a -> b of a counter-clockwise ring (its interior on the left): the
// direction b - a turned clockwise, (by - ay, -(bx - ax)); not normalised. In the differences'
// type D (theorem outward_normal_int64: both components fit int64 for in-range points).
template <class D>
struct Normal {
  D x, y;
};

template <class D>
constexpr Normal<D> outward_normal(D ax, D ay, D bx, D by) {
  return {by - ay, -(bx - ax)};
}

// --- Centroids (centroid.hpp) ---

// What edge a -> b of a ring adds to six times the ring's first moment along one axis: with c
// the axis's coordinate, (c_a + c_b) cross(a, b). Summed over the ring (the shoelace form of the
// moment integral) and divided by 3 times its twice-area, the centroid's coordinate.
template <class W>
constexpr W moment_term(W ca, W cb, W ax, W ay, W bx, W by) {
  return (ca + cb) * cross(ax, ay, bx, by);
}

// The centroid's denominator: 3 times the total twice-area.
template <class W>
constexpr W centroid_denominator(W twice_area) {
  return W(3) * twice_area;
}

// --- Grids of cells (segment and box grids of clip/) ---

// The number of integer values in [lo, hi] (a box's width or height in points).
template <class W>
constexpr W extent(W lo, W hi) {
  return hi - lo + W(1);
}

// How many cells of side s (>= 1) a box of w x h integer points spans: ceil(w/s) ceil(h/s).
template <class W>
constexpr W cells_covering(W w, W h, W s) {
  return floor_div(w + s - W(1), s) * floor_div(h + s - W(1), s);
}

// The number of points of a w x h block (cells of a grid, points of a box).
template <class W>
constexpr W block_size(W w, W h) {
  return w * h;
}

// The area of n cells of side s.
template <class W>
constexpr W cells_area(W s, W n) {
  return s * s * n;
}

// --- Shape builders (shapes.hpp): fixed point with `one` = 2^62, points within 2^35 ---------

// One step of the Taylor series of cosine and sine (shape_trig.cpp): the next term
// x^j / j! from the last, floor(floor(t x / one) / j), for 0 <= t, x <= one and j >= 1.
template <class W>
constexpr W taylor_step(W t, W x, W one, W j) {
  return floor_div(floor_div(t * x, one), j);
}

// The angle rem / q of an eighth of a turn in fixed point: floor(quarter_pi rem / q), for
// 0 <= rem <= q <= 2^48 and quarter_pi = pi/4 in fixed point.
template <class W>
constexpr W octant_angle(W quarter_pi, W rem, W q) {
  return floor_div(quarter_pi * rem, q);
}

// A point's offset along the rotated axes: (a c - b s) / one rounded to the nearest integer,
// halves up, for |a|, |b| <= 2^33 (a radius or half extent) and |c|, |s| <= one (a unit vector's
// components in fixed point). With b = 0 the offset of a point at distance a in direction c.
template <class W>
constexpr W rotated_offset(W a, W b, W c, W s, W one) {
  return floor_div(a * c - b * s + floor_div(one, W(2)), one);
}

// Where the segment from a (x < limit) to b (x > limit) crosses the line x = limit: at
// y = ay + num / den, with num = (limit - ax)(by - ay) and den = bx - ax > 0 (shape_cut.cpp
// rounds it toward the shape's inside with floor_div).
template <class W>
constexpr W crossing_numerator(W limit, W ax, W ay, W by) {
  return (limit - ax) * (by - ay);
}

}  // namespace edgeland::formulas
