// The library's one rounding function, formulas::round_half_up (used by round_to_grid):
// it computes in range, it returns the nearest integer with halves rounded up, and rounding
// the intersection of two in-range segments that meet gives an in-range coordinate.
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/point.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

// round_to_grid receives line_intersection's result normalized to den > 0 (predicates.cpp
// negates all three components when den < 0); each sign of den is its own theorem.
void rounded_intersection(Prover& p, bool negative_den) {
  const SegmentPairInputs s = segment_pair_inputs(p);
  const auto h =
      formulas::line_intersection<SymInt>(s.p0x, s.p0y, s.p1x, s.p1y, s.q0x, s.q0y, s.q1x, s.q1y);
  p.assume(negative_den ? h.den.term() < 0 : h.den.term() > 0);
  const SymInt x_num = negative_den ? -h.x_num : h.x_num;
  const SymInt y_num = negative_den ? -h.y_num : h.y_num;
  const SymInt den = negative_den ? -h.den : h.den;
  // Range of every step, 2*num + den and 2*den included, for ANY two non-parallel lines.
  const SymInt x = formulas::round_half_up<SymInt>(x_num, den);
  const SymInt y = formulas::round_half_up<SymInt>(y_num, den);

  // Premise of the output bound: the segments really meet, i.e. the crossing's parameters
  // t/den along p0->p1 and u/den along q0->q1 both lie in [0, 1] (p0 + (t/den)(p1 - p0) =
  // q0 + (u/den)(q1 - q0)). t is built with the kernel's own cross() over plain Z3 terms, so it
  // is the very subterm of x_num that the lemmas below generalize.
  const z3::expr p0x = s.p0x.term(), p0y = s.p0y.term(), q0x = s.q0x.term(), q0y = s.q0y.term();
  const z3::expr rx = s.p1x.term() - p0x, ry = s.p1y.term() - p0y;
  const z3::expr sx = s.q1x.term() - q0x, sy = s.q1y.term() - q0y;
  const z3::expr t = formulas::cross<z3::expr>(q0x - p0x, q0y - p0y, sx, sy);
  const z3::expr u = formulas::cross<z3::expr>(q0x - p0x, q0y - p0y, rx, ry);
  const z3::expr d = h.den.term();
  p.assume(negative_den ? d <= t && t <= 0 && d <= u && u <= 0
                        : 0 <= t && t <= d && 0 <= u && u <= d);
  // The exact point lies in the segment's bounding box, hence within the bound: x_num is
  // p0x*den + rx*t = p0x*(den - t) + p1x*t, a combination of two in-range coordinates with
  // weights of den's sign. Generalizing den, t and u to free integers keeps exactly that
  // argument and leaves Z3 a degree-2 question.
  const z3::expr bound = p.num(kCoordBound);
  const std::vector<z3::expr> parameters = {d, t, u};
  p.establish("-B*den <= x_num <= B*den",
              -bound * den.term() <= x_num.term() && x_num.term() <= bound * den.term(),
              parameters);
  p.establish("-B*den <= y_num <= B*den",
              -bound * den.term() <= y_num.term() && y_num.term() <= bound * den.term(),
              parameters);
  // ...and so does its rounding, as the bound is an integer: a fact about round_half_up of any
  // num, den > 0 with |num| <= B*den.
  p.establish("|rounded x| <= kCoordBound", -bound <= x.term() && x.term() <= bound,
              {x_num.term(), den.term()});
  p.establish("|rounded y| <= kCoordBound", -bound <= y.term() && y.term() <= bound,
              {y_num.term(), den.term()});
}

}  // namespace

std::vector<Theorem> rounding_theorems() {
  std::vector<Theorem> t;
  t.push_back({"round_intersection_den_positive_int128",
               "den > 0: rounding line_intersection fits Int128; for segments that meet the "
               "rounded point is within kCoordBound",
               128, [](Prover& p) { rounded_intersection(p, false); }});
  t.push_back({"round_intersection_den_negative_int128",
               "den < 0 (normalized by negation): rounding fits Int128; for segments that meet "
               "the rounded point is within kCoordBound",
               128, [](Prover& p) { rounded_intersection(p, true); }});
  t.push_back({"round_half_up_rule",
               "for den > 0, r = round_half_up(num, den) satisfies den(2r-1) <= 2num < den(2r+1): "
               "the nearest integer, halves up (|num|, den <= 2^125)",
               128, [](Prover& p) {
                 const SymInt num = p.integer("num", "-" + pow2(125), pow2(125));
                 const SymInt den = p.integer("den", "1", pow2(125));
                 const z3::expr r = formulas::round_half_up<SymInt>(num, den).term();
                 const z3::expr two_num = 2 * num.term(), d = den.term();
                 p.establish("den*(2r-1) <= 2*num < den*(2r+1)",
                             d * (2 * r - 1) <= two_num && two_num < d * (2 * r + 1));
               }});
  return t;
}

}  // namespace edgeland::proofs
