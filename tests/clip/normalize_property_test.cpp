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
      const std::int64_t dx =
          *rc::gen::element(kCoordBound - box->max.x, -kCoordBound - box->min.x);
      const std::int64_t dy =
          *rc::gen::element(kCoordBound - box->max.y, -kCoordBound - box->min.y);
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
                     std::string("normalize ") + fill_rule_name(rule) +
                         " rings = " + to_wkt(PolygonSet(rings.begin(), rings.end())));
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
  const PolygonSet a =
      *gen::polygon_set({0, 0}, *rc::gen::elementOf(std::vector<std::int64_t>{4, 40}));
  const FillRule rule = *rc::gen::element(FillRule::kEvenOdd, FillRule::kNonZero,
                                          FillRule::kPositive, FillRule::kNegative);
  std::vector<Ring> rings(a.begin(), a.end());
  if (rule == FillRule::kNegative)
    for (Ring& r : rings) std::reverse(r.begin(), r.end());
  const Outcome o = run_normalize(rings, rule);
  if (!o.ok()) RC_FAIL(o.error);
  RC_ASSERT(o.result->stats.vertices_snapped == 0u);
  const Rational diff =
      ExactRegion::of(o.result->polygons).apply(ClipOp::kXor, ExactRegion::of(a)).area();
  if (diff != 0)
    RC_FAIL(std::string("normalize ") + fill_rule_name(rule) +
            " changed the region of a valid set by " + diff.str() + "\n  A = " + to_wkt(a) +
            "\n  output = " + to_wkt(o.result->polygons));
  if (a.size() == 1) RC_ASSERT(o.result->polygons == canonical_form(a));
}

// OGC polygons of messy rings (self-crossing exteriors and holes, spikes, either orientation,
// holes anywhere): import_polygons gives a valid set within the contract of the region its
// contract defines, computed by the reference's own slabs with a winding number per ring.
RC_GTEST_PROP(ClipImportPolygons, MeetsTheContractOfTheOgcRegion, ()) {
  const std::int64_t r = *rc::gen::elementOf(std::vector<std::int64_t>{3, 6, 20, 1000});
  std::vector<std::vector<Ring>> polygons(static_cast<std::size_t>(*rc::gen::inRange(1, 4)));
  std::vector<Ring> rings;
  for (auto& polygon : polygons) {
    const int holes = *rc::gen::inRange(0, 3);
    for (int k = 0; k <= holes; ++k) {
      polygon.push_back(*messy_ring({0, 0}, k == 0 ? r : r / 2 + 1));
      rings.push_back(polygon.back());
    }
  }
  const Outcome o = run_import(polygons);
  if (!o.ok()) RC_FAIL(o.error);
  const FilledRegion exact = ogc_region(polygons);
  RC_ASSERT(exact.region.area() == exact.trapezoid_area);
  std::vector<Point64> inputs;
  for (const Ring& ring : rings) inputs.insert(inputs.end(), ring.begin(), ring.end());
  std::string described = "import_polygons:";
  for (const auto& polygon : polygons)
    described += " " + to_wkt(PolygonSet(polygon.begin(), polygon.end()));
  const ContractReport rep =
      check_contract(exact_region(exact.region), *o.result, inputs, described);
  if (!rep.ok()) RC_FAIL(rep.failure);
}

// Area of an import, exactly.
Rational imported_area(const std::vector<std::vector<Ring>>& polygons) {
  const Outcome o = run_import(polygons);
  EXPECT_TRUE(o.ok()) << o.error;
  return o.ok() ? ExactRegion::of(o.result->polygons).area() : Rational(-1);
}

// A bow tie (an exterior crossing itself at (5 5)) stands for both of its lobes, whichever
// way it is drawn: orienting it by its signed area, zero here, would keep one lobe.
TEST(ClipImportPolygons, BowTieExteriorKeepsBothLobes) {
  const Ring bow_tie{{0, 0}, {10, 0}, {0, 10}, {10, 10}};
  EXPECT_EQ(imported_area({{bow_tie}}), Rational(50));
  EXPECT_EQ(imported_area({{Ring(bow_tie.rbegin(), bow_tie.rend())}}), Rational(50));
  // Lobes of 200/3 and 50/3 meeting at (20/3 20/3): the smaller one turns against the total
  // area. Both count, give or take the rounding of the crossing (a few units here).
  const Rational unequal = imported_area({{{{0, 0}, {20, 0}, {0, 10}, {10, 10}}}});
  EXPECT_GT(unequal, Rational(250, 3) - Rational(5));
  EXPECT_LT(unequal, Rational(250, 3) + Rational(5));
}

// A bow-tie hole removes both of its lobes from its exterior.
TEST(ClipImportPolygons, BowTieHoleRemovesBothLobes) {
  const Ring square{{-10, -10}, {20, -10}, {20, 20}, {-10, 20}};
  const Ring bow_tie{{0, 0}, {10, 0}, {0, 10}, {10, 10}};
  EXPECT_EQ(imported_area({{square, bow_tie}}), Rational(900 - 50));
}

// A ring that winds twice around its core (a pentagram) stands for all it winds around, core
// included, like the non-zero rule; a valid polygon with a valid hole keeps its usual region.
TEST(ClipImportPolygons, PentagramAndValidPolygonWithHole) {
  const Ring pentagram{{0, 30}, {18, -24}, {-29, 9}, {29, 9}, {-18, -24}};
  const Outcome nonzero = run_normalize({pentagram}, FillRule::kNonZero);
  ASSERT_TRUE(nonzero.ok()) << nonzero.error;
  EXPECT_EQ(imported_area({{pentagram}}), ExactRegion::of(nonzero.result->polygons).area());
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring hole{{2, 2}, {2, 8}, {8, 8}, {8, 2}};
  EXPECT_EQ(imported_area({{square, hole}}), Rational(100 - 36));
  EXPECT_EQ(
      imported_area({{Ring(square.rbegin(), square.rend()), Ring(hole.rbegin(), hole.rend())}}),
      Rational(100 - 36));
}

// Rings given closed (last point = first, as WKT writes them) or with repeated points describe
// the same polygons.
TEST(ClipImportPolygons, ClosingAndRepeatedPointsChangeNothing) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring hole{{2, 2}, {2, 8}, {8, 8}, {8, 2}};
  const Outcome open = run_import({{square, hole}});
  const Outcome closed = run_import({{{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}},
                                      {{2, 2}, {2, 8}, {2, 8}, {8, 8}, {8, 2}, {2, 2}}}});
  ASSERT_TRUE(open.ok()) << open.error;
  ASSERT_TRUE(closed.ok()) << closed.error;
  EXPECT_EQ(open.result->polygons, closed.result->polygons);
  EXPECT_EQ(ExactRegion::of(open.result->polygons).area(), Rational(100 - 36));
}

}  // namespace
}  // namespace edgeland::test
