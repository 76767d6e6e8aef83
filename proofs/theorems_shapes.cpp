// The arithmetic of the shape builders (kernel/src/shapes.cpp and its helpers, shapes.hpp):
// the fixed-point Taylor series and octant angle of shape_trig.cpp, the rounded offsets of the
// corners, the hull's orientation and the cut's crossings on points within kShapeCoordBound
// (2^35: a centre within kCoordBound plus at most 2 kMaxShapeRadius + 1).
#include <cstdint>
#include <string>

#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/shapes.hpp"
#include "shape_hull.hpp"
#include "shape_trig.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

const std::string kOne = std::to_string(static_cast<std::int64_t>(detail::kFixedOne));
const std::string kRadius = std::to_string(kMaxShapeRadius);
const std::string kParts = std::to_string(static_cast<std::int64_t>(detail::kMaxTurnParts));
const std::string kPoints = std::to_string(detail::kShapeCoordBound);

SymInt fixed_one() { return SymInt(static_cast<std::int64_t>(detail::kFixedOne)); }

z3::expr within(Prover& p, const SymInt& v, const std::string& limit) {
  return -p.num(limit) <= v.term() && v.term() <= p.num(limit);
}

// A Taylor term t = x^j / j! <= one times x <= one, then divided by one and by j; the angle
// rem / q of an octant (rem <= q <= 2^47) times pi/4 in fixed point, divided by q.
void trig(Prover& p) {
  const SymInt t = p.integer("t", "0", kOne), x = p.integer("x", "0", kOne);
  const SymInt j = p.integer("j", "1", "64");
  formulas::taylor_step<SymInt>(t, x, fixed_one(), j);
  const SymInt q = p.integer("q", "1", kParts), rem = p.integer("rem", "0", kParts);
  p.assume(rem.term() <= q.term());
  const SymInt quarter_pi(static_cast<std::int64_t>(detail::kQuarterPiFixed));
  formulas::octant_angle<SymInt>(quarter_pi, rem, q);
}

// A corner's offset (a c - b s) / one with |a|, |b| <= kMaxShapeRadius and a unit vector's
// components |c|, |s| <= one: it fits, and it is at most 2 kMaxShapeRadius + 1, so a centre in
// range plus it stays within kShapeCoordBound.
void offset(Prover& p) {
  const SymInt a = p.integer("a", "-" + kRadius, kRadius);
  const SymInt b = p.integer("b", "-" + kRadius, kRadius);
  const SymInt c = p.integer("c", "-" + kOne, kOne), s = p.integer("s", "-" + kOne, kOne);
  const SymInt o = formulas::rotated_offset<SymInt>(a, b, c, s, fixed_one());
  const std::string most = std::to_string(2 * kMaxShapeRadius + 1);
  p.establish("|offset| <= 2 kMaxShapeRadius + 1", within(p, o, most));
  p.establish("centre + offset within kShapeCoordBound",
              p.num(std::to_string(kCoordBound)) + p.num(most) <= p.num(kPoints));
}

SymInt point_coordinate(Prover& p, const std::string& name) {
  return p.integer(name, "-" + kPoints, kPoints);
}

// The hull's orientation test on three points within kShapeCoordBound.
void hull_orient(Prover& p) {
  const SymInt ax = point_coordinate(p, "ax"), ay = point_coordinate(p, "ay");
  const SymInt bx = point_coordinate(p, "bx"), by = point_coordinate(p, "by");
  const SymInt cx = point_coordinate(p, "cx"), cy = point_coordinate(p, "cy");
  formulas::orient<SymInt>(ax, ay, bx, by, cx, cy);
}

// The crossing of a -> b (ax < limit < bx) with x = limit = kCoordBound, rounded either way:
// ay + floor(num / den) and ay - floor(-num / den). (That it lies between ay and by, so the cut
// keeps points within kShapeCoordBound, is the crossing's position on the segment; asking Z3
// costs 10 s for nothing the code depends on for overflow.)
void cut(Prover& p) {
  const SymInt ax = point_coordinate(p, "ax"), ay = point_coordinate(p, "ay");
  const SymInt bx = point_coordinate(p, "bx"), by = point_coordinate(p, "by");
  const SymInt limit(kCoordBound);
  p.assume(ax.term() < limit.term() && limit.term() < bx.term());
  const SymInt num = formulas::crossing_numerator<SymInt>(limit, ax, ay, by);
  const SymInt den = bx - ax;
  static_cast<void>(ay + floor_div(num, den));
  static_cast<void>(ay - floor_div(-num, den));
}

}  // namespace

std::vector<Theorem> shape_theorems() {
  return {
      Theorem("shape_trig_int128",
              "taylor_step and octant_angle (shape_trig.cpp) fit Int128 for Q62 terms and "
              "angles and turns of up to 2^47 parts",
              128, trig),
      Theorem("shape_offset_int128",
              "rotated_offset (shapes.cpp) fits Int128 for radii and half extents up to "
              "kMaxShapeRadius; the corners stay within kShapeCoordBound",
              128, offset),
      Theorem("shape_hull_orient_int128",
              "orient (shape_hull.cpp) fits Int128 for points within kShapeCoordBound", 128,
              hull_orient),
      Theorem("shape_cut_int128",
              "crossing_numerator and its rounding either way (shape_cut.cpp) fit Int128 for "
              "points within kShapeCoordBound",
              128, cut),
  };
}

}  // namespace edgeland::proofs
