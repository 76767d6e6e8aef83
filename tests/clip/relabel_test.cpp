// relabel() and cut_to_windows() (relabel.hpp): overlays of labeled regions in one arrangement.
// What must hold: every result is a valid set inside its window; each label's region meets the
// accuracy contract of clip.hpp against the exact relabeled region (CGAL); the decomposition is
// canonical (a function of the regions: equal regions described by different polygons give
// identical results); and the arguments are checked with typed errors.
#include "edgeland/clip/relabel.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>
#include <set>

#include "accuracy_contract.hpp"
#include "cgal_reference.hpp"
#include "generators.hpp"
#include "polygon_set_helpers.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {
namespace {

const ClipOptions kChecked{.checked = true};

Polygon box_polygon(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The polygons of one label.
PolygonSet of_label(const LabeledSet& s, RegionLabel l) {
  PolygonSet out;
  for (std::size_t i = 0; i < s.labels.size(); ++i)
    if (s.labels[i] == l) out.push_back(s.set.polygons()[i]);
  return out;
}

TEST(Relabel, FillsAShapeAcrossTwoMaterialsWithSharedBoundaries) {
  // Material 1 left, 2 right, sharing x = 10; fill the middle square with 3.
  const PolygonSet regions{box_polygon(0, 0, 10, 10), box_polygon(10, 0, 20, 10)};
  const std::vector<RegionLabel> labels{1, 2};
  const ValidSet shape(PolygonSet{box_polygon(5, 2, 15, 8)});
  const std::vector<RegionLabel> fill3{3, 3, 3, 3};
  const LabeledClipResult r =
      relabel(ValidSet(regions), labels, shape, {{0, 0}, {20, 10}}, fill3, kChecked);
  EXPECT_EQ(twice_area(of_label(r.regions, 3)), 2 * 60);
  EXPECT_EQ(twice_area(of_label(r.regions, 1)), 2 * (100 - 30));
  EXPECT_EQ(twice_area(of_label(r.regions, 2)), 2 * (100 - 30));
  // The middle is one polygon: the fill merged across the old boundary x = 10.
  EXPECT_EQ(of_label(r.regions, 3), (PolygonSet{box_polygon(5, 2, 15, 8)}));
  EXPECT_TRUE(validate(r.regions.set.polygons()).ok());
}

TEST(Relabel, CutsTheShapeToTheWindowInTheSameArrangement) {
  // Filling empty space with a shape reaching past the window fills only the window's part.
  const std::vector<RegionLabel> fill_empty{5};
  const ValidSet shape(PolygonSet{box_polygon(-10, -10, 5, 5)});
  const LabeledClipResult r =
      relabel(ValidSet(), {}, shape, {{0, 0}, {10, 10}}, fill_empty, kChecked);
  EXPECT_EQ(r.regions.set.polygons(), (PolygonSet{box_polygon(0, 0, 5, 5)}));
  EXPECT_EQ(r.regions.labels, (std::vector<RegionLabel>{5}));
}

TEST(Relabel, ReplaceTurnsOnlyOneMaterial) {
  const PolygonSet regions{box_polygon(0, 0, 10, 10), box_polygon(10, 0, 20, 10)};
  const std::vector<RegionLabel> labels{1, 2};
  std::vector<RegionLabel> table{0, 1, 7};  // 2 -> 7 inside; 0 stays 0, 1 stays 1
  const ValidSet shape(PolygonSet{box_polygon(0, 0, 20, 5)});
  const LabeledClipResult r =
      relabel(ValidSet(regions), labels, shape, {{0, 0}, {20, 10}}, table, kChecked);
  EXPECT_EQ(of_label(r.regions, 7), (PolygonSet{box_polygon(10, 0, 20, 5)}));
  EXPECT_EQ(of_label(r.regions, 1), (PolygonSet{box_polygon(0, 0, 10, 10)}));
  EXPECT_EQ(of_label(r.regions, 2), (PolygonSet{box_polygon(10, 5, 20, 10)}));
}

TEST(Relabel, RegionsWithAHoleAreCutAtCornersOnly) {
  // A frame of label 1 made of four rectangles (their corners lie on each other's edges, so the
  // arrangement has vertices in the middle of the frame's straight sides); the result must be
  // the canonical decomposition of the frame: the same as for the frame made of other pieces.
  const PolygonSet pieces_a{box_polygon(0, 0, 30, 10), box_polygon(0, 20, 30, 30),
                            box_polygon(0, 10, 10, 20), box_polygon(20, 10, 30, 20)};
  const PolygonSet pieces_b{box_polygon(0, 0, 10, 30), box_polygon(20, 0, 30, 30),
                            box_polygon(10, 0, 20, 10), box_polygon(10, 20, 20, 30)};
  const std::vector<RegionLabel> ones(4, 1);
  const Box64 w{{0, 0}, {30, 30}};
  const LabeledClipResult a = relabel(ValidSet(pieces_a), ones, ValidSet(), w, {}, kChecked);
  const LabeledClipResult b = relabel(ValidSet(pieces_b), ones, ValidSet(), w, {}, kChecked);
  EXPECT_EQ(a.regions.set.polygons(), b.regions.set.polygons());
  EXPECT_EQ(twice_area(a.regions.set.polygons()), 2 * (900 - 100));
  EXPECT_GE(a.regions.set.polygons().size(), 2u);  // a hole: cut into pieces
  for (const Polygon& p : a.regions.set.polygons())
    for (Point64 v : p) EXPECT_TRUE(v.x % 10 == 0 && v.y % 10 == 0) << to_wkt(p);
}

TEST(Relabel, RejectsArgumentsThatDoNotFit) {
  const PolygonSet regions{box_polygon(0, 0, 10, 10)};
  const Box64 w{{0, 0}, {10, 10}};
  auto reason = [&](auto&& call) {
    try {
      call();
    } catch (const InvalidOverlay& e) {
      return e.reason;
    }
    ADD_FAILURE() << "no InvalidOverlay";
    return InvalidOverlay::Reason::kBadWindow;
  };
  const std::vector<RegionLabel> none, zero{0}, one{1};
  EXPECT_EQ(reason([&] { relabel(ValidSet(regions), none, ValidSet(), w, {}); }),
            InvalidOverlay::Reason::kLabelCount);
  EXPECT_EQ(reason([&] { relabel(ValidSet(regions), zero, ValidSet(), w, {}); }),
            InvalidOverlay::Reason::kZeroLabel);
  EXPECT_EQ(reason([&] {
              relabel(ValidSet(regions), one, ValidSet(), {{0, 0}, {5, 10}}, {});
            }),
            InvalidOverlay::Reason::kOutsideWindow);
  EXPECT_EQ(reason([&] {
              relabel(ValidSet(regions), one, ValidSet(), {{0, 0}, {0, 10}}, {});
            }),
            InvalidOverlay::Reason::kBadWindow);
  const std::vector<Box64> overlapping{{{0, 0}, {6, 10}}, {{5, 0}, {10, 10}}};
  EXPECT_EQ(reason([&] { cut_to_windows(ValidSet(regions), one, overlapping); }),
            InvalidOverlay::Reason::kWindowsOverlap);
}

TEST(CutToWindows, QuartersMeetExactlyAlongTheCutLines) {
  // A triangle whose edges cross both cut lines at non-integer points.
  const PolygonSet regions{{{0, 0}, {97, 13}, {31, 89}}};
  const std::vector<RegionLabel> labels{4};
  const std::vector<Box64> quarters{
      {{0, 0}, {50, 50}}, {{50, 0}, {100, 50}}, {{0, 50}, {50, 100}}, {{50, 50}, {100, 100}}};
  const std::vector<LabeledSet> parts =
      cut_to_windows(ValidSet(regions), labels, quarters, kChecked);
  ASSERT_EQ(parts.size(), 4u);
  PolygonSet all;
  for (std::size_t w = 0; w < 4; ++w) {
    for (const Polygon& p : parts[w].set.polygons()) {
      for (Point64 v : p) EXPECT_TRUE(quarters[w].contains(v)) << to_wkt(p);
      all.push_back(p);
    }
    for (RegionLabel l : parts[w].labels) EXPECT_EQ(l, 4u);
  }
  // The pieces together are valid and are the triangle within snap rounding.
  EXPECT_TRUE(validate(all).ok());
  // Re-united (no crossings: the pieces only touch), they form one region again whose
  // boundary crosses the cut lines where the pieces met: no gap, no overlap.
  const std::vector<RegionLabel> fours(all.size(), 4);
  const LabeledClipResult merged =
      relabel(ValidSet(all), fours, ValidSet(), {{0, 0}, {100, 100}}, {}, kChecked);
  EXPECT_EQ(merged.stats.vertices_snapped, 0u);
  EXPECT_EQ(merged.regions.set.polygons().size(), 1u);
  EXPECT_EQ(twice_area(merged.regions.set.polygons()), twice_area(all));
}

// ---- properties -----------------------------------------------------------------------------

struct LabeledCase {
  PolygonSet regions, shape;
  std::vector<RegionLabel> labels, table;
  Box64 window;
};

void showValue(const LabeledCase& c, std::ostream& os) {
  os << "regions = " << to_wkt(c.regions) << "\n  labels =";
  for (RegionLabel l : c.labels) os << ' ' << l;
  os << "\n  shape = " << to_wkt(c.shape) << "\n  table =";
  for (RegionLabel l : c.table) os << ' ' << l;
  os << "\n  window = " << c.window.min.x << ' ' << c.window.min.y << ' ' << c.window.max.x << ' '
     << c.window.max.y;
}

rc::Gen<LabeledCase> labeled_case() {
  return rc::gen::exec([] {
    const OperandPair p = *gen::operand_pair();
    LabeledCase c;
    c.regions = p.a;
    c.shape = p.b;
    for (std::size_t i = 0; i < c.regions.size(); ++i) c.labels.push_back(*rc::gen::inRange(1, 4));
    const int table_size = *rc::gen::inRange(0, 5);
    for (int i = 0; i < table_size; ++i) c.table.push_back(*rc::gen::inRange(0, 4));
    Box64 w =
        bounding_box(c.regions).value_or(bounding_box(c.shape).value_or(Box64{{0, 0}, {1, 1}}));
    const std::int64_t grow = *rc::gen::inRange(0, 3);
    w = {{w.min.x - grow, w.min.y - grow}, {w.max.x + grow, w.max.y + grow}};
    w.min = {std::max(w.min.x, -kCoordBound), std::max(w.min.y, -kCoordBound)};
    w.max = {std::min(w.max.x, kCoordBound), std::min(w.max.y, kCoordBound)};
    if (w.min.x == w.max.x)
      w.max.x = w.min.x < kCoordBound ? w.min.x + 1 : w.max.x, w.min.x = w.max.x - 1;
    if (w.min.y == w.max.y)
      w.max.y = w.min.y < kCoordBound ? w.min.y + 1 : w.max.y, w.min.y = w.max.y - 1;
    c.window = w;
    return c;
  });
}

RegionLabel table_at(const LabeledCase& c, RegionLabel l) {
  return l < c.table.size() ? c.table[l] : l;
}

// The exact region of label L after the overlay.
ExactRegion exact_label(const LabeledCase& c, RegionLabel L, const ExactRegion& window,
                        const ExactRegion& shape_in_window,
                        const std::map<RegionLabel, ExactRegion>& before) {
  ExactRegion covered, out;
  for (const auto& [l, region] : before) {
    covered = covered.apply(ClipOp::kUnion, region);
    if (l == L) out = out.apply(ClipOp::kUnion, region.apply(ClipOp::kDifference, shape_in_window));
    if (table_at(c, l) == L)
      out = out.apply(ClipOp::kUnion, region.apply(ClipOp::kIntersection, shape_in_window));
  }
  if (table_at(c, 0) == L && L != 0)
    out = out.apply(
        ClipOp::kUnion,
        window.apply(ClipOp::kDifference, covered).apply(ClipOp::kIntersection, shape_in_window));
  return out;
}

RC_GTEST_PROP(RelabelProperty, EachLabelMeetsTheContractOfItsExactRegion, ()) {
  const LabeledCase c = *labeled_case();
  const LabeledClipResult r =
      relabel(ValidSet(c.regions), c.labels, ValidSet(c.shape, Operand::kClip), c.window, c.table,
              kChecked);
  const PolygonSet& out = r.regions.set.polygons();
  RC_ASSERT(validate(out).ok());
  for (const Polygon& p : out) {
    const Box64 b = *bounding_box(p);
    RC_ASSERT(c.window.contains(b.min));
    RC_ASSERT(c.window.contains(b.max));
  }
  for (RegionLabel l : r.regions.labels) RC_ASSERT(l != kNoRegion);
  const ExactRegion window = ExactRegion::of(
      PolygonSet{box_polygon(c.window.min.x, c.window.min.y, c.window.max.x, c.window.max.y)});
  const ExactRegion shape_in_window = ExactRegion::of(c.shape).apply(ClipOp::kIntersection, window);
  std::map<RegionLabel, ExactRegion> before;
  for (std::size_t i = 0; i < c.regions.size(); ++i)
    before[c.labels[i]] = before[c.labels[i]].apply(ClipOp::kUnion, ExactRegion::of(c.regions[i]));
  std::set<RegionLabel> labels(r.regions.labels.begin(), r.regions.labels.end());
  for (const auto& [l, _] : before) labels.insert(table_at(c, l));
  labels.insert(table_at(c, 0));
  labels.erase(kNoRegion);
  std::vector<Point64> inputs;
  for (const auto* s : {&c.regions, &c.shape})
    for (const Polygon& p : *s) inputs.insert(inputs.end(), p.begin(), p.end());
  for (RegionLabel L : labels) {
    ClipResult part;
    part.polygons = of_label(r.regions, L);
    part.stats = r.stats;
    const ContractReport report =
        check_contract(exact_region(exact_label(c, L, window, shape_in_window, before)), part,
                       inputs, "label " + std::to_string(L), ContractOptions{.random_points = 120});
    if (!report.ok()) RC_FAIL(report.failure);
  }
}

RC_GTEST_PROP(RelabelProperty, ResultIsItsOwnCanonicalDecomposition, ()) {
  const LabeledCase c = *labeled_case();
  const LabeledClipResult r =
      relabel(ValidSet(c.regions), c.labels, ValidSet(c.shape, Operand::kClip), c.window, c.table,
              kChecked);
  const LabeledClipResult again =
      relabel(r.regions.set, r.regions.labels, ValidSet(), c.window, {}, kChecked);
  RC_ASSERT(again.stats.vertices_snapped == 0u);
  RC_ASSERT(again.regions.set.polygons() == r.regions.set.polygons());
  RC_ASSERT(again.regions.labels == r.regions.labels);
}

// Regions on a grid of cells, each cell one of three labels or empty, described three ways:
// one square per cell, maximal row runs, maximal column runs. Holes, pinches and T-junctions
// all occur; the canonical decomposition must not see the difference.
// Ten grids per case: regions with holes need a few tries to come up.
RC_GTEST_PROP(RelabelProperty, EqualRegionsGiveIdenticalDecompositions, ()) {
  for (int round = 0; round < 10; ++round) {
    const int k = *rc::gen::inRange(2, 8);
    const std::int64_t size = *rc::gen::element<std::int64_t>(1, 3, 10);
    std::vector<std::vector<RegionLabel>> cell(k, std::vector<RegionLabel>(k));
    for (auto& row : cell)
      for (auto& l : row) l = *rc::gen::inRange<RegionLabel>(0, 4);
    auto describe = [&](int mode) {
      PolygonSet polys;
      std::vector<RegionLabel> labels;
      for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k;) {
          const RegionLabel l = mode == 2 ? cell[j][i] : cell[i][j];
          int e = j + 1;
          if (mode != 0)
            while (e < k && (mode == 2 ? cell[e][i] : cell[i][e]) == l) ++e;
          if (l != 0) {
            const std::int64_t a = i * size, b0 = j * size, b1 = e * size;
            polys.push_back(mode == 2 ? box_polygon(b0, a, b1, a + size)
                                      : box_polygon(a, b0, a + size, b1));
            labels.push_back(l);
          }
          j = e;
        }
      }
      return relabel(ValidSet(polys), labels, ValidSet(), {{0, 0}, {k * size, k * size}}, {},
                     kChecked);
    };
    const LabeledClipResult cells = describe(0), rows = describe(1), columns = describe(2);
    RC_ASSERT(cells.regions.set.polygons() == rows.regions.set.polygons());
    RC_ASSERT(cells.regions.labels == rows.regions.labels);
    RC_ASSERT(cells.regions.set.polygons() == columns.regions.set.polygons());
    RC_ASSERT(cells.regions.labels == columns.regions.labels);
  }
}

RC_GTEST_PROP(CutToWindowsProperty, PiecesAreTheRegionsInTheirWindows, ()) {
  const LabeledCase c = *labeled_case();
  const Box64 w = c.window;
  const std::int64_t mx = w.min.x + (w.max.x - w.min.x) / 2, my = w.min.y + (w.max.y - w.min.y) / 2;
  std::vector<Box64> windows;
  if (mx > w.min.x && my > w.min.y)
    windows = {{w.min, {mx, my}},
               {{mx, w.min.y}, {w.max.x, my}},
               {{w.min.x, my}, {mx, w.max.y}},
               {{mx, my}, w.max}};
  else
    windows = {w};
  const std::vector<LabeledSet> parts =
      cut_to_windows(ValidSet(c.regions), c.labels, windows, kChecked);
  RC_ASSERT(parts.size() == windows.size());
  PolygonSet all;
  std::vector<RegionLabel> all_labels;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    for (const Polygon& p : parts[i].set.polygons()) {
      const Box64 b = *bounding_box(p);
      RC_ASSERT(windows[i].contains(b.min));
      RC_ASSERT(windows[i].contains(b.max));
      all.push_back(p);
    }
    all_labels.insert(all_labels.end(), parts[i].labels.begin(), parts[i].labels.end());
  }
  RC_ASSERT(validate(all).ok());
  (void)all_labels;
  // Per window and label, the pieces meet the contract of the label's region in the window.
  std::map<RegionLabel, ExactRegion> by_label;
  for (std::size_t i = 0; i < c.regions.size(); ++i)
    by_label[c.labels[i]] =
        by_label[c.labels[i]].apply(ClipOp::kUnion, ExactRegion::of(c.regions[i]));
  std::vector<Point64> inputs;
  for (const Polygon& p : c.regions) inputs.insert(inputs.end(), p.begin(), p.end());
  for (std::size_t i = 0; i < windows.size(); ++i) {
    const Box64& b = windows[i];
    const ExactRegion window =
        ExactRegion::of(PolygonSet{box_polygon(b.min.x, b.min.y, b.max.x, b.max.y)});
    for (const auto& [l, region] : by_label) {
      ClipResult part;
      part.polygons = of_label(parts[i], l);
      part.stats.vertices_snapped = 1;  // pieces may be snapped at the cut lines
      const ContractReport report =
          check_contract(exact_region(region.apply(ClipOp::kIntersection, window)), part, inputs,
                         "window " + std::to_string(i) + " label " + std::to_string(l),
                         ContractOptions{.random_points = 80});
      if (!report.ok()) RC_FAIL(report.failure);
    }
  }
}

}  // namespace
}  // namespace edgeland::test
