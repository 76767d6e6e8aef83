// normalize(rings, fill_rule) (issue 4): arbitrary rings - self-intersecting, either
// orientation, overlapping, repeated points, spikes, zero-area parts - filled by each rule give
// a valid set meeting the accuracy contract against the exact filled region
// (tests/support/winding_reference.hpp: exact slab decomposition, then CGAL).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "generators.hpp"
#include "winding_reference.hpp"

namespace edgeland::test {
namespace {

// One messy ring: random points, with optional repeated points, a spike (a, b, a) and
// collinear runs; sometimes all on one line (zero area).
rc::Gen<Ring> messy_ring(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const Point64 lo{c.x - r, c.y - r}, hi{c.x + r, c.y + r};
    Ring ring = *rc::gen::container<Ring>(*rc::gen::inRange(1, 9), gen::point_in(lo, hi));
    const int flavour = static_cast<int>(*gen::coord(0, 7));
    if (flavour == 0 && !ring.empty()) ring.insert(ring.begin(), ring.front());  // repeat
    if (flavour == 1 && ring.size() >= 2) {  // spike out and back
      const std::size_t i = static_cast<std::size_t>(*gen::coord(0, std::int64_t(ring.size()) - 1));
      ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                  {*gen::point_in(lo, hi), ring[i]});
    }
    if (flavour == 2) {  // all points on one line: zero area
      const Point64 d{*gen::coord(-2, 2), *gen::coord(-2, 2)};
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::int64_t k = *gen::coord(-r / 3, r / 3);
        ring[i] = {c.x + k * d.x, c.y + k * d.y};
      }
    }
    if (flavour == 3 && ring.size() >= 2) {  // a collinear midpoint on an edge
      const Point64 a = ring[0], b = ring[1];
      if ((a.x + b.x) % 2 == 0 && (a.y + b.y) % 2 == 0)
        ring.insert(ring.begin() + 1, Point64{(a.x + b.x) / 2, (a.y + b.y) / 2});
    }
    if (flavour == 4) {  // a valid shape, in either orientation
      ring = *gen::shape(c, r);
      if (*rc::gen::arbitrary<bool>()) std::reverse(ring.begin(), ring.end());
    }
    return ring;
  });
}

rc::Gen<std::vector<Ring>> messy_rings() {
  return rc::gen::exec([] {
    const std::int64_t r = *rc::gen::elementOf(std::vector<std::int64_t>{3, 6, 20, 1000});
    std::vector<Ring> rings;
    const int n = *rc::gen::inRange(1, 4);
    for (int i = 0; i < n; ++i) rings.push_back(*messy_ring({0, 0}, r));
    const auto box = bounding_box(PolygonSet(rings.begin(), rings.end()));
    if (box && *gen::coord(0, 7) == 0) {  // move into a corner of the coordinate range
      const std::int64_t dx = *rc::gen::element(kCoordBound - box->max.x, -kCoordBound - box->min.x);
      const std::int64_t dy = *rc::gen::element(kCoordBound - box->max.y, -kCoordBound - box->min.y);
      for (Ring& ring : rings)
        for (Point64& p : ring) p = {p.x + dx, p.y + dy};
    }
    return rings;
  });
}

void check_fill(FillRule rule) {
  const std::vector<Ring> rings = *messy_rings();
  const Outcome o = run_normalize(rings, rule);
  if (!o.ok()) RC_FAIL(o.error);
  const FilledRegion exact = filled_region(rings, rule);
  // The reference checks itself: its trapezoids tile the region CGAL built from them.
  RC_ASSERT(exact.region.area() == exact.trapezoid_area);
  std::vector<Point64> inputs;
  for (const Ring& r : rings) inputs.insert(inputs.end(), r.begin(), r.end());
  const ContractReport rep =
      check_contract(exact_region(exact.region), *o.result, inputs,
                     std::string("normalize ") + fill_rule_name(rule) + " rings = " +
                         to_wkt(PolygonSet(rings.begin(), rings.end())));
  if (!rep.ok()) RC_FAIL(rep.failure);
}

RC_GTEST_PROP(ClipNormalize, EvenOddFillMeetsTheAccuracyContract, ()) {
  check_fill(FillRule::kEvenOdd);
}
RC_GTEST_PROP(ClipNormalize, NonZeroFillMeetsTheAccuracyContract, ()) {
  check_fill(FillRule::kNonZero);
}
RC_GTEST_PROP(ClipNormalize, PositiveFillMeetsTheAccuracyContract, ()) {
  check_fill(FillRule::kPositive);
}
RC_GTEST_PROP(ClipNormalize, NegativeFillMeetsTheAccuracyContract, ()) {
  check_fill(FillRule::kNegative);
}

// A valid set is already normalized: its rings have no crossings, so nothing is snapped and
// every rule but kNegative gives exactly its region (kNegative: exactly the region of the
// reversed rings). A single valid polygon comes back as its canonical form.
RC_GTEST_PROP(ClipNormalize, ValidSetsKeepTheirExactRegion, ()) {
  const PolygonSet a = *gen::polygon_set({0, 0}, *rc::gen::elementOf(std::vector<std::int64_t>{4, 40}));
  const FillRule rule = *rc::gen::element(FillRule::kEvenOdd, FillRule::kNonZero,
                                          FillRule::kPositive, FillRule::kNegative);
  std::vector<Ring> rings(a.begin(), a.end());
  if (rule == FillRule::kNegative)
    for (Ring& r : rings) std::reverse(r.begin(), r.end());
  const Outcome o = run_normalize(rings, rule);
  if (!o.ok()) RC_FAIL(o.error);
  RC_ASSERT(o.result->stats.vertices_snapped == 0u);
  const Rational diff = ExactRegion::of(o.result->polygons).apply(ClipOp::kXor, ExactRegion::of(a)).area();
  if (diff != 0)
    RC_FAIL(std::string("normalize ") + fill_rule_name(rule) + " changed the region of a valid set by " +
            diff.str() + "\n  A = " + to_wkt(a) + "\n  output = " + to_wkt(o.result->polygons));
  if (a.size() == 1) RC_ASSERT(o.result->polygons == canonical_form(a));
}

}  // namespace
}  // namespace edgeland::test
