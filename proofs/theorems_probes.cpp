// The arithmetic of the kernel's probes that the clipper and the landscape call: rays
// (ray.cpp: ray_contact, NearestHit, first_hit), exact-point tests (predicates.cpp: is_exactly),
// the closed-pixel test of snap rounding (pixel.cpp: segment_meets_closed_pixel) and the sizing
// of uniform grids (grid_cells.cpp). Before issue 17 these products were computed inside clip/
// with no proof; now each is a formula of formulas.hpp proven here.
#include <string>

#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/grid_cells.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/ray.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

struct RayInputs {
  SymInt ox, oy, dx, dy, px, py, qx, qy;
};

// A ray from an in-range origin with |direction components| <= kMaxRayDirection, and an
// in-range edge p -> q.
RayInputs ray_inputs(Prover& p) {
  const std::string d = std::to_string(kMaxRayDirection);
  return {p.coordinate("ox"),          p.coordinate("oy"), p.integer("dx", "-" + d, d),
          p.integer("dy", "-" + d, d), p.coordinate("px"), p.coordinate("py"),
          p.coordinate("qx"),          p.coordinate("qy")};
}

formulas::RayEdge<SymInt> edge_parameters(const RayInputs& r) {
  return formulas::ray_edge<SymInt>(r.ox, r.oy, r.dx, r.dy, r.px, r.py, r.qx, r.qy);
}

// ray_contact's crossing branch: den != 0, normalized to den > 0 by negating all three (as
// ray.cpp does when den < 0), t_num >= 0; then the hit point ray_point(o, d, t_num, den).
void crossing_point(Prover& p, bool negative_den) {
  const RayInputs r = ray_inputs(p);
  const formulas::RayEdge<SymInt> e = edge_parameters(r);
  p.assume(negative_den ? e.den.term() < 0 : e.den.term() > 0);
  const SymInt t = negative_den ? -e.t_num : e.t_num;
  const SymInt den = negative_den ? -e.den : e.den;
  p.assume(t.term() >= 0);
  formulas::ray_point<SymInt>(r.ox, r.oy, r.dx, r.dy, t, den);
}

// ray_contact's parallel branch: the edge's nearer end, parameter ray_projection / dot(d, d)
// with a projection >= 0 (the origin itself when the edge reaches behind it: t = 0).
void along_point(Prover& p) {
  const RayInputs r = ray_inputs(p);
  const SymInt t = formulas::ray_projection<SymInt>(r.ox, r.oy, r.dx, r.dy, r.px, r.py);
  const SymInt dd = formulas::squared_length<SymInt>(r.dx, r.dy);
  p.assume(t.term() >= 0 && dd.term() > 0);
  formulas::ray_point<SymInt>(r.ox, r.oy, r.dx, r.dy, t, dd);
}

}  // namespace

std::vector<Theorem> probe_theorems() {
  std::vector<Theorem> t;
  t.push_back({"ray_edge_int128",
               "ray_edge (ray_contact, NearestHit, first_hit): t_num, u_num, den, their "
               "negations, ray_projection and dot(d, d) fit Int128 for |d| <= kMaxRayDirection",
               128, [](Prover& p) {
                 const RayInputs r = ray_inputs(p);
                 const formulas::RayEdge<SymInt> e = edge_parameters(r);
                 -e.t_num;
                 -e.u_num;
                 -e.den;
                 formulas::ray_projection<SymInt>(r.ox, r.oy, r.dx, r.dy, r.px, r.py);
                 formulas::squared_length<SymInt>(r.dx, r.dy);
               }});
  t.push_back({"ray_point_crossing_int128",
               "den > 0: ray_point of a crossing (t_num >= 0) fits Int128", 128,
               [](Prover& p) { crossing_point(p, false); }});
  t.push_back({"ray_point_crossing_negated_int128",
               "den < 0, negated as ray_contact does: ray_point fits Int128", 128,
               [](Prover& p) { crossing_point(p, true); }});
  t.push_back({"ray_point_along_int128",
               "a ray along an edge: ray_point at projection / dot(d, d) fits Int128", 128,
               along_point});
  t.push_back({"scaled_int128",
               "is_exactly: an in-range coordinate times a denominator |den| <= 2^95 fits Int128",
               128, [](Prover& p) {
                 const SymInt c = p.coordinate("c");
                 const SymInt den = p.integer("den", "-" + pow2(95), pow2(95));
                 formulas::scaled<SymInt>(c, den);
               }});
  t.push_back({"taxicab_length_int64",
               "|bx - ax| + |by - ay| (pixel_line_slack) fits int64 for in-range points", 64,
               [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::taxicab_length<SymInt>(in.ax, in.ay, in.bx, in.by);
               }});
  t.push_back({"outward_normal_int64",
               "outward_normal (edge_normal.hpp: a ray hit's normal) fits int64 for in-range "
               "points, the negation included",
               64, [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::outward_normal<SymInt>(in.ax, in.ay, in.bx, in.by);
               }});
  t.push_back({"pixel_line_slack_int128",
               "pixel_line_slack (segment_meets_closed_pixel): 2 |orient| and the slack fit "
               "Int128",
               128, [](Prover& p) {
                 const PointTripleInputs in = point_triple_inputs(p);
                 formulas::pixel_line_slack<SymInt, SymInt>(in.ax, in.ay, in.bx, in.by, in.cx,
                                                            in.cy);
               }});
  t.push_back({"grid_sizing_int128",
               "point_count, cells_covering, cells_area, block_size (grid_cells.cpp) fit Int128 "
               "for in-range boxes, sides and counts up to kMaxGridSide",
               128, [](Prover& p) {
                 const std::string most = std::to_string(kMaxGridSide);
                 const SymInt x0 = p.coordinate("min_x"), x1 = p.coordinate("max_x");
                 const SymInt y0 = p.coordinate("min_y"), y1 = p.coordinate("max_y");
                 p.assume(x0.term() <= x1.term() && y0.term() <= y1.term());
                 const SymInt side = p.integer("side", "1", most);
                 const SymInt n = p.integer("n", "0", most);
                 const SymInt columns = p.integer("columns", "0", most);
                 const SymInt rows = p.integer("rows", "0", most);
                 const SymInt w = formulas::extent<SymInt>(x0, x1);
                 const SymInt h = formulas::extent<SymInt>(y0, y1);
                 formulas::block_size<SymInt>(w, h);
                 formulas::cells_covering<SymInt>(w, h, side);
                 formulas::cells_area<SymInt>(side, n);
                 formulas::block_size<SymInt>(columns, rows);
               }});
  return t;
}

}  // namespace edgeland::proofs
