// Locality (clip.hpp, LOCALITY; issue 4): an input edge farther than 2 units from the other
// operand's boundary appears in the output unchanged, vertex for vertex, or not at all.
//
// "Unchanged" is checked on the canonical output, which removes collinear vertices: the edge
// e must lie entirely on ONE output edge f (collinear, e within f), and each endpoint of e
// where its own input ring turns (a corner, not a collinear vertex) must still be a vertex of
// the output - when the ring's other edge at that corner is far as well. (If that other edge
// is near, it may be rerouted by snap rounding so that it continues e in a straight line;
// the canonical form then removes the corner, and e survives only as part of a longer edge.
// "Vertex for vertex" and "no collinear vertices" cannot both hold there.)
// "Not at all" means no output edge overlaps e in a piece of positive length.
// Anything else (e cut short, e partly present, a corner of e moved) breaks locality.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <unordered_set>

#include "cgal_reference.hpp"
#include "checked_clip.hpp"
#include "generators.hpp"

namespace edgeland::test {
namespace {

bool on_closed_segment(Point64 p, Point64 a, Point64 b) {
  return cross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Collinear with a common piece of positive length.
bool overlaps(const Segment& e, const Segment& f) {
  if (cross(e.a, e.b, f.a) != 0 || cross(e.a, e.b, f.b) != 0) return false;
  // Project on the direction of e: [0, |e|^2] against f's interval.
  auto t = [&](Point64 p) {
    return Int128(p.x - e.a.x) * (e.b.x - e.a.x) + Int128(p.y - e.a.y) * (e.b.y - e.a.y);
  };
  const Int128 len = t(e.b), f0 = std::min(t(f.a), t(f.b)), f1 = std::max(t(f.a), t(f.b));
  return std::max<Int128>(0, f0) < std::min(len, f1);
}

bool far_from(const Segment& e, const PolygonSet& other) {
  const Box64 eb{{std::min(e.a.x, e.b.x) - 2, std::min(e.a.y, e.b.y) - 2},
                 {std::max(e.a.x, e.b.x) + 2, std::max(e.a.y, e.b.y) + 2}};
  for (const Polygon& p : other)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Segment f = ring_edge(p, i);
      const Box64 fb{{std::min(f.a.x, f.b.x), std::min(f.a.y, f.b.y)},
                     {std::max(f.a.x, f.b.x), std::max(f.a.y, f.b.y)}};
      if (!eb.overlaps(fb)) continue;
      if (!segments_farther_than(e, f, 4)) return false;
    }
  return true;
}

// Empty string when every far edge of `input` is kept whole or removed whole.
std::string check_locality(const PolygonSet& input, const PolygonSet& other,
                           const PolygonSet& out) {
  std::vector<Segment> out_edges;
  std::unordered_set<Point64, Point64Hash> out_vertices;
  for (const Polygon& p : out)
    for (std::size_t i = 0; i < p.size(); ++i) {
      out_edges.push_back(ring_edge(p, i));
      out_vertices.insert(p[i]);
    }
  for (const Polygon& p : input)
    for (std::size_t i = 0, n = p.size(); i < n; ++i) {
      const Segment e = ring_edge(p, i);
      if (!far_from(e, other)) continue;
      bool touched = false, kept = false;
      for (const Segment& f : out_edges) {
        if (!overlaps(e, f)) continue;
        touched = true;
        if (on_closed_segment(e.a, f.a, f.b) && on_closed_segment(e.b, f.a, f.b)) kept = true;
      }
      const std::string where = "(" + std::to_string(e.a.x) + ' ' + std::to_string(e.a.y) +
                                ", " + std::to_string(e.b.x) + ' ' + std::to_string(e.b.y) + ")";
      if (!touched) continue;
      if (!kept) return "far edge " + where + " is only partly in the output";
      const Point64 before = p[(i + n - 1) % n], after = p[(i + 2) % n];
      const bool start_corner =
          cross(before, e.a, e.b) != 0 && far_from(Segment{before, e.a}, other);
      const bool end_corner = cross(e.a, e.b, after) != 0 && far_from(Segment{e.b, after}, other);
      if ((start_corner && !out_vertices.contains(e.a)) ||
          (end_corner && !out_vertices.contains(e.b)))
        return "far edge " + where + " lost a corner vertex";
    }
  return {};
}

void check_op(ClipOp op, const OperandPair& p) {
  const Outcome o = run_clip(op, p.a, p.b);
  if (!o.ok()) RC_FAIL(o.error);
  for (int side = 0; side < 2; ++side) {
    const std::string f = side == 0 ? check_locality(p.a, p.b, o.result->polygons)
                                    : check_locality(p.b, p.a, o.result->polygons);
    if (!f.empty())
      RC_FAIL(std::string(side == 0 ? "subject " : "clip ") + f + "\n  " + op_name(op) +
              "\n  A = " + to_wkt(p.a) + "\n  B = " + to_wkt(p.b) +
              "\n  output = " + to_wkt(o.result->polygons));
  }
}

// A larger set carved or filled by one small shape somewhere inside it: most edges are far.
rc::Gen<OperandPair> carving_pair() {
  return rc::gen::exec([] {
    const PolygonSet world = *gen::polygon_set({0, 0}, 40);
    const Point64 at = *gen::point_in({-40, -40}, {40, 40});
    const PolygonSet tool = keep_valid({*gen::shape(at, *gen::coord(2, 8))});
    return *rc::gen::arbitrary<bool>() ? gen::pair_of("carving", world, tool)
                                       : gen::pair_of("carving-tool-first", tool, world);
  });
}

rc::Gen<OperandPair> locality_pair() {
  return rc::gen::weightedOneOf<OperandPair>({{1, gen::operand_pair()}, {1, carving_pair()}});
}

RC_GTEST_PROP(ClipLocality, UnionKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kUnion, p);
}
RC_GTEST_PROP(ClipLocality, IntersectionKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kIntersection, p);
}
RC_GTEST_PROP(ClipLocality, DifferenceKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kDifference, p);
}
RC_GTEST_PROP(ClipLocality, XorKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kXor, p);
}

}  // namespace
}  // namespace edgeland::test
