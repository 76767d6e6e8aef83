// Overflow freedom of the formulas behind the kernel's predicates (predicates.cpp): every
// intermediate of orient, dot_from and line_intersection fits Int128 for in-range input.
#include "edgeland/kernel/formulas.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {

PointTripleInputs point_triple_inputs(Prover& p) {
  return {p.coordinate("ax"), p.coordinate("ay"), p.coordinate("bx"),
          p.coordinate("by"), p.coordinate("cx"), p.coordinate("cy")};
}

SegmentPairInputs segment_pair_inputs(Prover& p) {
  return {p.coordinate("p0x"), p.coordinate("p0y"), p.coordinate("p1x"), p.coordinate("p1y"),
          p.coordinate("q0x"), p.coordinate("q0y"), p.coordinate("q1x"), p.coordinate("q1y")};
}

namespace {

formulas::Homogeneous<SymInt> intersect_lines(const SegmentPairInputs& s) {
  return formulas::line_intersection<SymInt>(s.p0x, s.p0y, s.p1x, s.p1y, s.q0x, s.q0y, s.q1x,
                                             s.q1y);
}

}  // namespace

std::vector<Theorem> predicate_theorems() {
  std::vector<Theorem> t;
  t.push_back({"orient_int128",
               "orient(a, b, c) (orient_det, orientation, intersect) never overflows Int128", 128,
               [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::orient<SymInt>(in.ax, in.ay, in.bx, in.by, in.cx, in.cy);
               }});
  t.push_back({"orient_differences_int64",
               "b - a and c - a of orient_widening (orient_det) fit int64 for in-range points", 64,
               [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::orient_differences<SymInt>(in.ax, in.ay, in.bx, in.by, in.cx, in.cy);
               }});
  t.push_back(
      {"orient_widening_int128", "orient_widening (orient_det): its products and result fit Int128",
       128, [](Prover& p) {
         const PointTripleInputs in = point_triple_inputs(p);
         formulas::orient_widening<SymInt, SymInt>(in.ax, in.ay, in.bx, in.by, in.cx, in.cy);
       }});
  t.push_back({"dot_from_int128", "dot_from(a, b, c) (dot_sign, along) never overflows Int128", 128,
               [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::dot_from<SymInt>(in.ax, in.ay, in.bx, in.by, in.cx, in.cy);
               }});
  t.push_back({"dot_widening_int128",
               "dot_widening (dot_sign, along, projection): its products and sum fit Int128", 128,
               [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::dot_widening<SymInt, SymInt>(in.ax, in.ay, in.bx, in.by, in.cx, in.cy);
               }});
  t.push_back({"line_intersection_int128",
               "line_intersection: x_num, y_num, den and all their intermediates fit Int128", 128,
               [](Prover& p) { intersect_lines(segment_pair_inputs(p)); }});
  t.push_back(
      {"line_intersection_normalize_int128",
       "negating x_num, y_num, den when den < 0 (predicates.cpp line_intersection) fits Int128",
       128, [](Prover& p) {
         const auto h = intersect_lines(segment_pair_inputs(p));
         p.assume(h.den.term() < 0);  // the branch that negates
         -h.x_num;
         -h.y_num;
         -h.den;
       }});
  return t;
}

}  // namespace edgeland::proofs
