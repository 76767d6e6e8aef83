// Locality (clip.hpp, LOCALITY; issue 4): an input edge farther than 2 units from the other
// operand's boundary appears in the output unchanged, vertex for vertex, or not at all, as the
// operation demands (the oracle and its exact reading: tests/support/locality_check.hpp).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checked_clip.hpp"
#include "generators.hpp"
#include "locality_check.hpp"

namespace edgeland::test {
namespace {

void check_op(ClipOp op, const OperandPair& p, Locality reading) {
  const Outcome o = run_clip(op, p.a, p.b);
  if (!o.ok()) RC_FAIL(o.error);
  for (int side = 0; side < 2; ++side) {
    const std::string f = side == 0
                              ? check_locality(op, p.a, p.b, true, o.result->polygons, reading)
                              : check_locality(op, p.b, p.a, false, o.result->polygons, reading);
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

// Whether every vertex of the set is farther than one unit from every edge of the set that
// does not end at it (exact): no feature thinner than a pixel, no vertex on a foreign edge.
bool without_subpixel_features(const PolygonSet& s) {
  for (const Polygon& p : s)
    for (const Point64& v : p)
      for (const Polygon& q : s)
        for (std::size_t i = 0; i < q.size(); ++i) {
          const Segment e = ring_edge(q, i);
          if (e.a == v || e.b == v) continue;
          if (!segments_farther_than(Segment{v, v}, e, 1)) return false;
        }
  return true;
}

PolygonSet keep_fat(const PolygonSet& s) {
  PolygonSet out;
  for (const Polygon& p : s) {
    out.push_back(p);
    if (!without_subpixel_features(out)) out.pop_back();
  }
  return out;
}

// The operation's reading (far edges kept exactly where the operation keeps them) on inputs
// with no feature thinner than a pixel, where snap rounding never has to collapse a far part.
RC_GTEST_PROP(ClipLocality, FarEdgesOfInputsWithoutSubpixelFeaturesAreKeptAsTheOperationSays, ()) {
  OperandPair p = *locality_pair();
  p.a = keep_fat(p.a);
  p.b = keep_fat(p.b);
  RC_TAG(p.scenario);
  check_op(
      *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor),
      p, Locality::kOperation);
}

RC_GTEST_PROP(ClipLocality, UnionKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kUnion, p, Locality::kLiteral);
}
RC_GTEST_PROP(ClipLocality, IntersectionKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kIntersection, p, Locality::kLiteral);
}
RC_GTEST_PROP(ClipLocality, DifferenceKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kDifference, p, Locality::kLiteral);
}
RC_GTEST_PROP(ClipLocality, XorKeepsFarEdgesWholeOrDropsThem, ()) {
  const OperandPair p = *locality_pair();
  RC_TAG(p.scenario);
  check_op(ClipOp::kXor, p, Locality::kLiteral);
}

}  // namespace
}  // namespace edgeland::test
