// Properties of the landscape under random edit sequences (issue 15, "Verification"):
//   * every invariant holds after every edit (checked mode), change sets say exactly what
//     changed (ids, polygons, areas);
//   * the materials are those of the exact history of the edits (pointwise, and areas against
//     CGAL) up to the accumulated snap-rounding bound, in a deep tree and in a one-cell landscape
//     alike (the seam property);
//   * material_at, crossings, raycast and overlaps agree with brute force over all polygons;
//   * snapshots restore the state hash; save/load gives the same state.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>
#include <set>
#include <sstream>

#include "cgal_reference.hpp"
#include "edgeland/clip/relabel.hpp"
#include "generators.hpp"
#include "landscape_cases.hpp"
#include "landscape_oracle.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

std::map<PolygonId, FlatPolygon> by_id(const Landscape& l) {
  std::map<PolygonId, FlatPolygon> out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    out[v.id] = {v.material, *v.polygon, *bounding_box(*v.polygon)};
    return true;
  });
  return out;
}

// Applies one edit or batch by `apply_it` to a checked landscape and checks its change set: ids
// removed and added exactly, unchanged polygons keeping their ids, areas moved as it says.
template <class Apply>
void check_reported_change(Landscape& l, Apply&& apply_it) {
  const std::map<PolygonId, FlatPolygon> before = by_id(l);
  std::array<Int128, 6> area_before{};
  for (int m = 0; m < 6; ++m) area_before[m] = l.twice_area(m);
  const ChangeSet cs = apply_it();
  const std::map<PolygonId, FlatPolygon> after = by_id(l);
  std::map<PolygonId, FlatPolygon> expected = before;
  for (PolygonId id : cs.removed) {
    RC_ASSERT(before.count(id) == 1u);
    RC_ASSERT(after.count(id) == 0u);
    expected.erase(id);
  }
  for (const ChangeSet::Added& a : cs.added) {
    RC_ASSERT(before.count(a.id) == 0u);
    RC_ASSERT(after.count(a.id) == 1u);
    RC_ASSERT(after.at(a.id).ring == a.polygon);
    RC_ASSERT(after.at(a.id).material == a.material);
    expected[a.id] = after.at(a.id);
  }
  RC_ASSERT(expected.size() == after.size());
  // An unchanged polygon keeps its id (a game rebuilds only what changed).
  std::map<std::pair<Material, Polygon>, PolygonId> old_ids;
  for (const auto& [id, p] : before) old_ids[{p.material, p.ring}] = id;
  for (const auto& [id, p] : after) {
    const auto it = old_ids.find({p.material, p.ring});
    if (it != old_ids.end()) RC_ASSERT(it->second == id);
  }
  for (const auto& [id, p] : after)
    RC_ASSERT(expected.count(id) == 1u && expected.at(id).ring == p.ring);
  std::map<Material, Int128> delta;
  for (const auto& [m, d] : cs.twice_area_delta) delta[m] = d;
  Int128 total = 0;
  for (int m = 0; m < 6; ++m) {
    RC_ASSERT(l.twice_area(m) - area_before[m] == delta[m]);
    total += delta[m];
  }
  RC_ASSERT(total == 0);
}

RC_GTEST_PROP(LandscapeProperty, EditsKeepEveryInvariantAndReportWhatChanged, ()) {
  const LandscapeCase c = *landscape_case();
  Landscape l(c.world, c.fill, c.config);
  l.set_checked(true);
  for (const LandscapeEdit& e : c.edits) check_reported_change(l, [&] { return apply(l, e); });
  const LandscapeReport report = l.check();
  if (!report.ok()) RC_FAIL(report.problems.front());
  RC_CLASSIFY(l.stats().cells > 1, "several cells");
  RC_CLASSIFY(l.stats().polygons > 10, "more than 10 polygons");
}

// The same for frame batches (Landscape::apply_batch): one change set says what the whole batch
// changed.
RC_GTEST_PROP(LandscapeProperty, BatchesKeepEveryInvariantAndReportWhatChanged, ()) {
  const LandscapeCase c = *landscape_case();
  Landscape l(c.world, c.fill, c.config);
  l.set_checked(true);
  for (const std::vector<Edit>& batch : batches_of(c))
    check_reported_change(l, [&] { return l.apply_batch(batch); });
  const LandscapeReport report = l.check();
  if (!report.ok()) RC_FAIL(report.problems.front());
  RC_CLASSIFY(l.stats().cells > 1, "several cells");
}

// A loose but sound drift bound: each snap rounding moves a boundary by at most sqrt(2)/2 < 3/4,
// and a boundary point is rounded at most by each edit and each level of splitting, twice over
// for cells that merged and split again.
Rational drift_bound(std::size_t edits, std::uint32_t deepest) {
  return Rational(3, 4) * Rational(static_cast<long long>(2 * edits + 2 * deepest + 1));
}

// Whether q is farther than d from the boundary of every shape and of the world.
bool clear_of_boundaries(const QPoint& q, const std::vector<ExactRegion>& shapes,
                         const ExactRegion& world, const Rational& d) {
  const Rational d2 = d * d;
  if (world.boundary_within(q, d2)) return false;
  for (const ExactRegion& s : shapes)
    if (s.boundary_within(q, d2)) return false;
  return true;
}

Material exact_material(const LandscapeCase& c, const std::vector<ExactRegion>& shapes,
                        const ExactRegion& world, const QPoint& q) {
  if (world.locate(q) != ExactRegion::Location::kInside) return kEmpty;
  Material m = c.fill;
  for (std::size_t i = 0; i < c.edits.size(); ++i)
    m = apply_pointwise(c.edits[i], m, shapes[i].locate(q) == ExactRegion::Location::kInside);
  return m;
}

Polygon box_polygon(const Box64& b) {
  return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
}

// The landscapes (each after the case's edits, one by one or in batches) hold the materials of
// the exact history at points farther than d from every boundary, and areas within the bands of
// width d around the boundaries (against CGAL). Returns that band's area.
Rational check_exact_history(const LandscapeCase& c, const std::vector<const Landscape*>& got,
                             const Rational& d) {
  std::vector<ExactRegion> shapes;
  for (const LandscapeEdit& e : c.edits) shapes.push_back(ExactRegion::of(e.shape));
  const ExactRegion world = ExactRegion::of(box_polygon(c.world));
  std::vector<std::vector<FlatPolygon>> polys;
  for (const Landscape* l : got) polys.push_back(flatten(*l));
  std::size_t tested = 0;
  for (int k = 0; k < 150; ++k) {
    const QPoint q{Rational(*gen::coord(4 * c.world.min.x - 8, 4 * c.world.max.x + 8), 4),
                   Rational(*gen::coord(4 * c.world.min.y - 8, 4 * c.world.max.y + 8), 4)};
    if (!clear_of_boundaries(q, shapes, world, d)) continue;
    ++tested;
    const Material want = exact_material(c, shapes, world, q);
    for (const std::vector<FlatPolygon>& p : polys) RC_ASSERT(material_brute(p, q) == want);
  }
  RC_TAG(tested > 0 ? "points tested" : "no point clear of boundaries");
  // Areas against CGAL: the difference lies in the bands of width d around the boundaries.
  std::map<Material, ExactRegion> exact;
  if (c.fill != kEmpty) exact[c.fill] = world;
  for (std::size_t i = 0; i < c.edits.size(); ++i) {
    const LandscapeEdit& e = c.edits[i];
    const ExactRegion s = shapes[i].apply(ClipOp::kIntersection, world);
    ExactRegion solid;
    for (const auto& [m, r] : exact) solid = solid.apply(ClipOp::kUnion, r);
    std::map<Material, ExactRegion> next;
    for (const auto& [m, r] : exact) {
      next[m] = next[m].apply(ClipOp::kUnion, r.apply(ClipOp::kDifference, s));
      const Material to = apply_pointwise(e, m, true);
      if (to != kEmpty)
        next[to] = next[to].apply(ClipOp::kUnion, r.apply(ClipOp::kIntersection, s));
    }
    const Material from_empty = apply_pointwise(e, kEmpty, true);
    if (from_empty != kEmpty)
      next[from_empty] =
          next[from_empty].apply(ClipOp::kUnion, s.apply(ClipOp::kDifference, solid));
    exact = std::move(next);
  }
  Rational band = 0;
  for (const ExactRegion& s : shapes)
    band += 2 * d * Rational(s.perimeter_ceil()) +
            Rational(22, 7) * d * d * Rational(static_cast<long long>(s.boundary_cycles()));
  band += 2 * d * Rational(world.perimeter_ceil()) + Rational(22, 7) * d * d;
  for (const auto& [m, r] : exact) {
    for (const Landscape* l : got) {
      const Rational area = Rational(static_cast<long long>(l->twice_area(m))) / 2;
      RC_ASSERT(abs(area - r.area()) <= band);
    }
  }
  return band;
}

LandscapeConfig one_cell_config() {
  LandscapeConfig one_cell;
  one_cell.edge_cap = 1u << 30;
  one_cell.merge_below = 1u << 29;
  return one_cell;
}

RC_GTEST_PROP(LandscapeProperty, MaterialsAreTheExactHistoryAwayFromBoundaries, ()) {
  const LandscapeCase c = *landscape_case(5);
  std::uint32_t deepest = 0;
  const Landscape tree = run_case(c, c.config, &deepest);
  const Landscape single = run_case(c, one_cell_config());
  RC_ASSERT(single.stats().cells == 1u);
  check_exact_history(c, {&tree, &single}, drift_bound(c.edits.size(), deepest));
}

// Frame batches (Landscape::apply_batch, spatial/README.md "Frame batches"): the edits in
// batches of 1-4, each batch rounded once, hold the exact history within the drift bound of as
// many edits as there are batches, in a deep tree and in one cell, where the same edits one by
// one need the bound of all the edits. The edits one by one are still there and give their own
// result: every material's area in the two differs by at most the sum of the two bands. Every
// batch passes checked mode (run_batches) and check().
RC_GTEST_PROP(LandscapeProperty, BatchesAreTheExactHistoryWithinOneRoundingPerBatch, ()) {
  const LandscapeCase c = *landscape_case(6);
  const std::vector<std::vector<Edit>> batches = batches_of(c);
  std::uint32_t deepest = 0, deepest_one_by_one = 0;
  const Landscape tree = run_batches(c, c.config, batches, &deepest);
  const Landscape single = run_batches(c, one_cell_config(), batches);
  const Landscape one_by_one = run_case(c, c.config, &deepest_one_by_one);
  RC_ASSERT(single.stats().cells == 1u);
  RC_ASSERT(tree.check().ok() && single.check().ok());
  RC_CLASSIFY(batches.size() < c.edits.size(), "batches of several");
  const Rational batch_band =
      check_exact_history(c, {&tree, &single}, drift_bound(batches.size(), deepest));
  const Rational one_band =
      check_exact_history(c, {&one_by_one}, drift_bound(c.edits.size(), deepest_one_by_one));
  for (int m = 0; m < 6; ++m) {
    const Rational a = Rational(static_cast<long long>(tree.twice_area(m))) / 2;
    const Rational b = Rational(static_cast<long long>(one_by_one.twice_area(m))) / 2;
    RC_ASSERT(abs(a - b) <= batch_band + one_band);
  }
}

// Segment endpoints that hit the interesting places: vertices, cell lines, the world's sides,
// random points.
Point64 probe_point(const Landscape& l, const std::vector<FlatPolygon>& polys) {
  const Box64& w = l.world();
  const int kind = *rc::gen::inRange(0, 5);
  if (kind == 0 && !polys.empty()) {
    const FlatPolygon& p = polys[*rc::gen::inRange<std::size_t>(0, polys.size())];
    return p.ring[*rc::gen::inRange<std::size_t>(0, p.ring.size())];
  }
  if (kind == 1) {  // a cell line of a quadtree over the world
    const std::int64_t mx = w.min.x + (w.max.x - w.min.x) / 2;
    return {mx, *gen::coord(w.min.y - 4, w.max.y + 4)};
  }
  if (kind == 2) {  // a side line of the world, which is no surface for rays
    const bool vertical = *rc::gen::arbitrary<bool>(), high = *rc::gen::arbitrary<bool>();
    if (vertical) return {high ? w.max.x : w.min.x, *gen::coord(w.min.y - 4, w.max.y + 4)};
    return {*gen::coord(w.min.x - 4, w.max.x + 4), high ? w.max.y : w.min.y};
  }
  return {*gen::coord(w.min.x - 4, w.max.x + 4), *gen::coord(w.min.y - 4, w.max.y + 4)};
}

Rational rational(const Fraction& f) {
  auto big = [](Int128 v) {
    const bool negative = v < 0;
    const unsigned __int128 u =
        negative ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
    BigInt r(static_cast<unsigned long long>(u >> 64));
    r <<= 64;
    r += BigInt(static_cast<unsigned long long>(u));
    return negative ? BigInt(-r) : r;
  };
  return Rational(big(f.num), big(f.den));
}

RC_GTEST_PROP(LandscapeProperty, QueriesAgreeWithBruteForce, ()) {
  const LandscapeCase c = *landscape_case(5);
  const Landscape l = run_case(c, c.config);
  const std::vector<FlatPolygon> polys = flatten(l);
  for (int k = 0; k < 20; ++k) {
    const Point64 p = probe_point(l, polys);
    RC_ASSERT(l.material_at(p) == material_brute(polys, {Rational(p.x), Rational(p.y)}));
  }
  for (int k = 0; k < 4; ++k) {
    const Point64 a = probe_point(l, polys);
    Point64 b = probe_point(l, polys);
    if (*rc::gen::inRange(0, 3) == 0) b = {a.x + *gen::coord(-300, 300), a.y};  // horizontal
    if (a == b) continue;
    const std::vector<MaterialCrossing> got = l.crossings(a, b);
    const std::vector<BruteCrossing> want = profile_brute(polys, l.world(), a, b);
    RC_ASSERT(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      RC_ASSERT(rational(got[i].t) == want[i].t);
      RC_ASSERT(got[i].before == want[i].before);
      RC_ASSERT(got[i].after == want[i].after);
    }
    std::optional<BruteCrossing> first;
    for (const BruteCrossing& w : want)
      if (w.after != kEmpty) {
        first = w;
        break;
      }
    const auto hit = l.raycast(a, b);
    RC_ASSERT(hit.has_value() == first.has_value());
    if (hit) {
      RC_ASSERT(rational(hit->t) == first->t);
      RC_ASSERT(hit->after == first->after);
      RC_ASSERT(round_to_grid(hit->point) == hit->rounded);
    }
  }
  for (int k = 0; k < 6; ++k) {
    const Point64 a = probe_point(l, polys);
    const Box64 box{a, {a.x + *gen::coord(1, 40), a.y + *gen::coord(1, 40)}};
    const ExactRegion region = ExactRegion::of(box_polygon(box));
    std::set<Material> want;
    for (const FlatPolygon& p : polys)
      if (!ExactRegion::of(p.ring).apply(ClipOp::kIntersection, region).empty())
        want.insert(p.material);
    const std::vector<Material> got = l.overlaps(box);
    RC_ASSERT(std::set<Material>(got.begin(), got.end()) == want);
    const std::vector<Material> general = l.overlaps(ValidSet(PolygonSet{box_polygon(box)}));
    RC_ASSERT(general == got);
  }
}

RC_GTEST_PROP(LandscapeProperty, RestoringASnapshotRestoresTheState, ()) {
  const LandscapeCase c = *landscape_case(6);
  Landscape l(c.world, c.fill, c.config);
  const std::size_t at = *rc::gen::inRange<std::size_t>(0, c.edits.size());
  for (std::size_t i = 0; i < at; ++i) apply(l, c.edits[i]);
  const Landscape snapshot = l;
  const std::uint64_t hash = l.state_hash();
  for (std::size_t i = at; i < c.edits.size(); ++i) apply(l, c.edits[i]);
  RC_ASSERT(snapshot.state_hash() == hash);
  l = snapshot;
  RC_ASSERT(l.state_hash() == hash);
  RC_ASSERT(l.check().ok());
}

RC_GTEST_PROP(LandscapeProperty, SaveAndLoadGiveTheSameState, ()) {
  const LandscapeCase c = *landscape_case(6);
  const Landscape l = run_case(c, c.config);
  std::stringstream file;
  l.save(file);
  const Landscape back = Landscape::load(file);
  RC_ASSERT(back.state_hash() == l.state_hash());
  RC_ASSERT(flatten(back).size() == flatten(l).size());
  for (int m = 0; m < 6; ++m) RC_ASSERT(back.twice_area(m) == l.twice_area(m));
}

}  // namespace
}  // namespace edgeland::test

namespace edgeland::test {
namespace {

// Whether every line x = k * step or y = k * step that meets the convex polygon cuts it along a
// stretch at least w long (or misses it): then no cut is thin enough for snap rounding to
// close it on one side. Exact: each crossing is a fraction of small integers.
bool cuts_are_wide(const Polygon& p, std::int64_t w, std::int64_t step) {
  for (int axis = 0; axis < 2; ++axis) {
    auto along = [axis](Point64 v) { return axis == 0 ? v.x : v.y; };
    auto across = [axis](Point64 v) { return axis == 0 ? v.y : v.x; };
    std::int64_t lo = along(p[0]), hi = lo;
    for (Point64 v : p) lo = std::min(lo, along(v)), hi = std::max(hi, along(v));
    for (std::int64_t line = (lo / step) * step; line <= hi; line += step) {
      if (line < lo) continue;
      // The crossings as fractions num / den with den > 0; the cut is their spread.
      std::vector<std::pair<Int128, Int128>> at;
      for (std::size_t i = 0, n = p.size(); i < n; ++i) {
        const Point64 a = p[i], b = p[(i + 1) % n];
        if ((along(a) - line) * (along(b) - line) > 0 || along(a) == along(b)) continue;
        Int128 num = Int128(across(a)) * (along(b) - along(a)) +
                     Int128(line - along(a)) * (across(b) - across(a));
        Int128 den = along(b) - along(a);
        if (den < 0) num = -num, den = -den;
        at.push_back({num, den});
      }
      for (const auto& [n1, d1] : at)
        for (const auto& [n2, d2] : at)
          if (n1 * d2 > n2 * d1 && n1 * d2 - n2 * d1 < Int128(w) * d1 * d2) return false;
    }
  }
  return true;
}

// Seams (issue 15, "Seams leave no trace"): a convex shape filled into an empty world cut into
// a grid comes out as pieces, one per cell it covers; re-united across the cell lines they form
// one polygon again without any rounding: every piece meets its neighbour exactly along the
// line, with no gap, no sliver of empty space and no overlap. (A part of a shape thinner than a
// unit where a line cuts it may round away on one side: snap rounding, not a seam; such shapes
// are left out.)
RC_GTEST_PROP(LandscapeSeams, PiecesAcrossCellLinesReuniteExactly, ()) {
  const std::int64_t size = *rc::gen::element<std::int64_t>(64, 256, 4096);
  LandscapeConfig grid;
  grid.grid_depth = *rc::gen::inRange(1, 5);
  grid.min_cell_size = 1;
  Landscape l({{0, 0}, {size, size}}, kEmpty, grid);
  l.set_checked(true);
  const Polygon shape = *gen::convex({size / 2, size / 2}, size / 2);
  const std::int64_t step = std::max<std::int64_t>(1, size >> grid.grid_depth);
  RC_PRE(cuts_are_wide(shape, 2, step));
  RC_LOG() << "grid depth " << grid.grid_depth << " size " << size << " shape " << to_wkt(shape)
           << "\n";
  l.fill(PolygonSet{shape}, 1);
  PolygonSet pieces;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    pieces.push_back(*v.polygon);
    return true;
  });
  RC_ASSERT(!pieces.empty());
  const std::vector<RegionLabel> ones(pieces.size(), 1);
  const LabeledClipResult united =
      relabel(ValidSet(pieces), ones, ValidSet(), l.world(), {}, ClipOptions{.checked = true});
  RC_ASSERT(united.stats.vertices_snapped == 0u);
  RC_ASSERT(united.regions.set.polygons().size() == 1u);
  RC_ASSERT(twice_area(united.regions.set.polygons()) == l.twice_area(1));
}

// A single edit rounds once, in a tree cut in advance as in one cell: the two worlds may differ
// only within 1.5 units (the clipper's accuracy contract) of the shape's or the world's
// boundary, and there both are within it of the exact answer.
RC_GTEST_PROP(LandscapeSeams, ATreeAndOneCellDifferOnlyNearTheShape, ()) {
  const LandscapeCase c = *landscape_case(1);
  LandscapeConfig grid;
  grid.grid_depth = *rc::gen::inRange(1, 4);
  grid.min_cell_size = 1;
  grid.tree = c.config.tree;
  LandscapeConfig one_cell;
  one_cell.edge_cap = 1u << 30;
  one_cell.merge_below = 1u << 29;
  const Landscape tree = run_case(c, grid), single = run_case(c, one_cell);
  const std::vector<ExactRegion> shapes{ExactRegion::of(c.edits[0].shape)};
  const ExactRegion world = ExactRegion::of(box_polygon(c.world));
  const std::vector<FlatPolygon> tree_polys = flatten(tree), single_polys = flatten(single);
  for (int k = 0; k < 150; ++k) {
    const QPoint q{Rational(*gen::coord(4 * c.world.min.x - 8, 4 * c.world.max.x + 8), 4),
                   Rational(*gen::coord(4 * c.world.min.y - 8, 4 * c.world.max.y + 8), 4)};
    if (!clear_of_boundaries(q, shapes, world, Rational(3, 2))) continue;
    const Material want = exact_material(c, shapes, world, q);
    RC_ASSERT(material_brute(tree_polys, q) == want);
    RC_ASSERT(material_brute(single_polys, q) == want);
  }
}

}  // namespace
}  // namespace edgeland::test
