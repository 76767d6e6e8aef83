// Stage tests of an edit's steps that had none (spatial/README.md, "An edit"): where a cell
// splits (split_boxes), which ids new cells take (IdSource, match_ids), and what differs between
// the old and the new tree (diff, change_set), and the builder that makes the next state from the
// current one (EditBuilder).
#include <gtest/gtest.h>

#include <vector>

#include "cell_split.hpp"
#include "changes.hpp"
#include "edit.hpp"
#include "ids.hpp"
#include "node.hpp"
#include "split_content.hpp"
#include "state_of.hpp"

namespace edgeland {
namespace {

using detail::NodePtr;

Polygon square(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

NodePtr cell(const Box64& box, const PolygonSet& polygons, const std::vector<RegionLabel>& labels,
             const std::vector<PolygonId>& ids) {
  return detail::make_cell(box, 1, {ValidSet(polygons), labels}, ids);
}

// ---- split_boxes -----------------------------------------------------------------------------

TEST(SplitBoxes, AQuadtreeCutsBothSidesAtTheirIntegerMidpoints) {
  const std::vector<Box64> c = detail::split_boxes({{0, 0}, {101, 64}}, LandscapeConfig{});
  ASSERT_EQ(c.size(), 4u);  // x before y, low before high
  EXPECT_EQ(c[0], (Box64{{0, 0}, {50, 32}}));
  EXPECT_EQ(c[1], (Box64{{50, 0}, {101, 32}}));
  EXPECT_EQ(c[2], (Box64{{0, 32}, {50, 64}}));
  EXPECT_EQ(c[3], (Box64{{50, 32}, {101, 64}}));
}

TEST(SplitBoxes, AKdTreeCutsTheLongerSideXOnTies) {
  LandscapeConfig kd;
  kd.tree = TreeKind::kKdTree;
  EXPECT_EQ(detail::split_boxes({{0, 0}, {64, 200}}, kd),
            (std::vector<Box64>{{{0, 0}, {64, 100}}, {{0, 100}, {64, 200}}}));
  EXPECT_EQ(detail::split_boxes({{0, 0}, {64, 64}}, kd),
            (std::vector<Box64>{{{0, 0}, {32, 64}}, {{32, 0}, {64, 64}}}));
}

TEST(SplitBoxes, ASideAtTheMinimumSizeIsNotCut) {
  LandscapeConfig config;
  config.min_cell_size = 16;
  EXPECT_EQ(detail::split_boxes({{0, 0}, {16, 64}}, config),
            (std::vector<Box64>{{{0, 0}, {16, 32}}, {{0, 32}, {16, 64}}}));
  EXPECT_FALSE(detail::can_split({{0, 0}, {16, 16}}, config));
  EXPECT_TRUE(detail::can_split({{0, 0}, {16, 17}}, config));
}

TEST(SplitBoxes, ChildrenPartitionTheParentAtTheWholeRange) {
  // I4 at the coordinate bound: the children's areas add up to the parent's, their interiors
  // are disjoint, and none is flat.
  const Box64 world{{-kCoordBound, -kCoordBound}, {kCoordBound, kCoordBound}};
  for (TreeKind kind : {TreeKind::kQuadtree, TreeKind::kKdTree}) {
    LandscapeConfig config;
    config.tree = kind;
    const std::vector<Box64> c = detail::split_boxes(world, config);
    Int128 area = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_LT(c[i].min.x, c[i].max.x);
      EXPECT_LT(c[i].min.y, c[i].max.y);
      area += Int128(c[i].max.x - c[i].min.x) * (c[i].max.y - c[i].min.y);
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_FALSE(c[i].min.x < c[j].max.x && c[j].min.x < c[i].max.x &&
                     c[i].min.y < c[j].max.y && c[j].min.y < c[i].max.y);
    }
    EXPECT_TRUE(area == Int128(world.max.x - world.min.x) * (world.max.y - world.min.y));
  }
}

TEST(SplitBoxes, AnInnerNodeDerivesEachChildsBoxFromItsCutLines) {
  // Node::child_box (what box queries descend by, without reading the children) is the box
  // split_boxes gave the child, for both tree kinds, cuts in one or both directions, odd sizes.
  const std::vector<Box64> boxes{{{0, 0}, {101, 64}},
                                 {{-7, 3}, {9, 200}},
                                 {{0, 0}, {16, 64}},
                                 {{0, 0}, {64, 16}},
                                 {{-5, -5}, {5, 5}}};
  for (TreeKind kind : {TreeKind::kQuadtree, TreeKind::kKdTree}) {
    LandscapeConfig config;
    config.tree = kind;
    config.min_cell_size = 16;
    for (const Box64& box : boxes) {
      if (!detail::can_split(box, config)) continue;
      const std::vector<Box64> parts = detail::split_boxes(box, config);
      std::vector<NodePtr> children;
      for (const Box64& part : parts) children.push_back(cell(part, {}, {}, {}));
      const NodePtr inner = detail::make_inner(box, 0, children);
      for (std::uint32_t i = 0; i < parts.size(); ++i) EXPECT_EQ(inner->child_box(i), parts[i]);
    }
  }
}

// ---- cut_to_children -------------------------------------------------------------------------

// A cell's canonical content: two regions (rock 1, ore 2) from `relabel` within the box.
LabeledSet canonical_content(const Box64& box, const PolygonSet& polygons,
                             const std::vector<RegionLabel>& labels) {
  return relabel(ValidSet(polygons), labels, ValidSet(), box, {}).regions;
}

void expect_parts_equal(const std::vector<LabeledSet>& a, const std::vector<LabeledSet>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].set.polygons(), b[i].set.polygons()) << i;
    EXPECT_EQ(a[i].labels, b[i].labels) << i;
  }
}

TEST(CutToChildren, ContentInOneChildIsCutToWindowsAnswerWithoutAnArrangement) {
  const Box64 box{{0, 0}, {64, 64}};
  const LandscapeConfig config;
  const std::vector<Box64> boxes = detail::split_boxes(box, config);
  // An ore square inside a rock frame, all in the upper right quarter, touching its lines.
  const LabeledSet content = relabel(ValidSet(PolygonSet{square(32, 32, 60, 60)}), {{1}},
                                     ValidSet(PolygonSet{square(40, 40, 50, 50)}), box, {{0, 2}})
                                 .regions;
  ASSERT_GT(content.labels.size(), 2u);
  const std::vector<LabeledSet> parts = detail::cut_to_children(content, boxes, {});
  expect_parts_equal(parts, cut_to_windows(content.set, content.labels, boxes));
  EXPECT_EQ(parts[3].set.polygons(), content.set.polygons());
  EXPECT_TRUE(parts[0].labels.empty() && parts[1].labels.empty() && parts[2].labels.empty());
}

TEST(CutToChildren, ContentOverACellLineIsCutInOneArrangement) {
  const Box64 box{{0, 0}, {64, 64}};
  const std::vector<Box64> boxes = detail::split_boxes(box, LandscapeConfig{});
  const LabeledSet content =
      canonical_content(box, {{{10, 10}, {50, 13}, {47, 50}, {12, 41}}}, {1});
  const std::vector<LabeledSet> parts = detail::cut_to_children(content, boxes, {.checked = true});
  expect_parts_equal(parts, cut_to_windows(content.set, content.labels, boxes));
  for (const LabeledSet& p : parts) EXPECT_FALSE(p.labels.empty());
}

// ---- ids -------------------------------------------------------------------------------------

TEST(IdSource, FindsEqualPolygonsInEveryCellBelowANode) {
  const NodePtr a = cell({{0, 0}, {10, 10}}, {square(0, 0, 5, 5)}, {1}, {7});
  const NodePtr b =
      cell({{10, 0}, {20, 10}}, {square(10, 0, 12, 3), square(14, 4, 16, 6)}, {2, 1}, {8, 9});
  const NodePtr c = cell({{0, 10}, {10, 20}}, {}, {}, {});
  const NodePtr d = cell({{10, 10}, {20, 20}}, {}, {}, {});
  const NodePtr inner = detail::make_inner({{0, 0}, {20, 20}}, 0, {a, b, c, d});
  const detail::IdSource ids(inner);
  EXPECT_EQ(ids.find(square(14, 4, 16, 6), 1), 9u);
  EXPECT_EQ(ids.find(square(0, 0, 5, 5), 1), 7u);
  EXPECT_EQ(ids.find(square(0, 0, 5, 5), 2), 0u);  // same ring, another material: a new polygon
  EXPECT_EQ(ids.find(square(0, 0, 5, 6), 1), 0u);
  EXPECT_EQ(detail::IdSource(b).find(square(0, 0, 5, 5), 1), 0u);  // not below b
}

TEST(IdSource, MatchIdsKeepsEqualPolygonsAndNumbersTheRestInOrder) {
  const NodePtr old =
      cell({{0, 0}, {10, 10}}, {square(0, 0, 5, 5), square(6, 6, 8, 8)}, {1, 2}, {3, 4});
  const LabeledSet now{
      ValidSet(PolygonSet{square(0, 0, 5, 5), square(6, 0, 9, 2), square(6, 6, 8, 8)}), {1, 1, 3}};
  PolygonId next = 20;
  EXPECT_EQ(detail::match_ids(detail::IdSource(old), now, next),
            (std::vector<PolygonId>{3, 20, 21}));
  EXPECT_EQ(next, 22u);
}

// ---- diff and change_set ---------------------------------------------------------------------

TEST(Diff, VisitsOnlyWhatChangedAndReportsItsPolygons) {
  const NodePtr a = cell({{0, 0}, {10, 10}}, {square(0, 0, 5, 5)}, {1}, {1});
  const NodePtr b = cell({{10, 0}, {20, 10}}, {square(10, 0, 20, 10)}, {1}, {2});
  const NodePtr c = cell({{0, 10}, {10, 20}}, {}, {}, {});
  const NodePtr d = cell({{10, 10}, {20, 20}}, {}, {}, {});
  const NodePtr old_root = detail::make_inner({{0, 0}, {20, 20}}, 0, {a, b, c, d});
  EXPECT_TRUE(detail::diff(old_root, old_root).old_cells.empty());
  // b carved to a smaller square (a new polygon), the rest shared.
  const NodePtr b2 = cell({{10, 0}, {20, 10}}, {square(10, 0, 15, 10)}, {1}, {3});
  const NodePtr new_root = detail::make_inner({{0, 0}, {20, 20}}, 0, {a, b2, c, d});
  const detail::Changes changes = detail::diff(old_root, new_root);
  EXPECT_EQ(changes.old_cells, std::vector<NodePtr>{b});
  EXPECT_EQ(changes.new_cells, std::vector<NodePtr>{b2});
  EXPECT_EQ(changes.new_inner, std::vector<NodePtr>{new_root});
  const ChangeSet cs = detail::change_set(changes);
  EXPECT_EQ(cs.removed, std::vector<PolygonId>{2});
  ASSERT_EQ(cs.added.size(), 1u);
  EXPECT_EQ(cs.added[0].id, 3u);
  EXPECT_EQ(cs.added[0].polygon, square(10, 0, 15, 10));
  // Twice the area: rock loses 5 x 10, empty space gains it (the deltas sum to 0).
  ASSERT_EQ(cs.twice_area_delta.size(), 2u);
  for (const auto& [m, delta] : cs.twice_area_delta) {
    EXPECT_TRUE(m == kEmpty || m == Material(1));
    EXPECT_TRUE(delta == (m == kEmpty ? 100 : -100));
  }
}

TEST(Diff, ASplitCellIsReplacedByAllItsChildren) {
  const NodePtr whole = cell({{0, 0}, {20, 20}}, {square(0, 0, 20, 10)}, {1}, {5});
  const NodePtr low = cell({{0, 0}, {20, 10}}, {square(0, 0, 20, 10)}, {1}, {5});
  const NodePtr high = cell({{0, 10}, {20, 20}}, {}, {}, {});
  LandscapeConfig kd;
  kd.tree = TreeKind::kKdTree;
  ASSERT_EQ(detail::split_boxes({{0, 0}, {20, 20}}, kd).size(), 2u);
  const NodePtr split = detail::make_inner({{0, 0}, {20, 20}}, 0, {low, high});
  const detail::Changes changes = detail::diff(whole, split);
  EXPECT_EQ(changes.old_cells, std::vector<NodePtr>{whole});
  EXPECT_EQ(changes.new_cells, (std::vector<NodePtr>{low, high}));
  const ChangeSet cs = detail::change_set(changes);
  EXPECT_TRUE(cs.removed.empty());  // the polygon kept its id across the split
  EXPECT_TRUE(cs.added.empty());
}

// ---- EditBuilder -----------------------------------------------------------------------------

Polygon diamond(Point64 c, std::int64_t r) {
  return {{c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}};
}

// A worn world of several materials over many cells (the edits cross cell lines).
Landscape worn() {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 16;
  Landscape l({{0, 0}, {512, 512}}, 1, config);
  for (std::int64_t i = 0; i < 12; ++i) {
    l.carve(PolygonSet{diamond({40 + 37 * i, 60 + 29 * i}, 23 + i)});
    l.fill(PolygonSet{diamond({470 - 31 * i, 90 + 33 * i}, 17 + 2 * i)}, 2 + i % 3);
  }
  return l;
}

// One edit's result as the builder makes it: one step of `shape` and `table`.
detail::EditResult build_one(const detail::LandscapeState& state, const detail::EditTable& table,
                             const ValidSet& shape) {
  const RelabelStep step{&shape, table.table};
  return detail::EditBuilder(state, std::span(&step, 1)).build();
}

// The builder's next state and change set are what the landscape's own edit commits and returns
// (the same tree by hash, ids, areas, one more edit).
TEST(EditBuilder, BuildsWhatTheLandscapesEditCommits) {
  Landscape l = worn();
  const detail::LandscapeState current = test::state_of(l);
  const PolygonSet shape{diamond({250, 250}, 140), diamond({60, 450}, 30)};
  const detail::EditTable table = detail::EditTable::replace(1, 5);
  const detail::EditResult built = build_one(current, table, ValidSet(shape));

  const ChangeSet committed = l.replace(shape, 1, 5);
  const detail::LandscapeState after = test::state_of(l);
  EXPECT_NE(built.next.root->hash, current.root->hash);
  EXPECT_EQ(built.next.root->hash, after.root->hash);
  EXPECT_EQ(built.next.next_id, after.next_id);
  EXPECT_EQ(*built.next.areas, *after.areas);
  EXPECT_EQ(built.next.edits, current.edits + 1);
  EXPECT_EQ(built.changes.removed, committed.removed);
  ASSERT_EQ(built.changes.added.size(), committed.added.size());
  for (std::size_t i = 0; i < committed.added.size(); ++i) {
    EXPECT_EQ(built.changes.added[i].id, committed.added[i].id);
    EXPECT_EQ(built.changes.added[i].polygon, committed.added[i].polygon);
  }
  EXPECT_EQ(built.changes.twice_area_delta, committed.twice_area_delta);
}

// A shape outside the world, or empty, builds the same tree (shared, not copied) and an empty
// change set; it still counts as an edit.
TEST(EditBuilder, AShapeMissingTheWorldKeepsTheTree) {
  const detail::LandscapeState current = test::state_of(worn());
  const detail::EditTable table = detail::EditTable::carve();
  const detail::EditResult outside =
      build_one(current, table, ValidSet(PolygonSet{diamond({900, 900}, 50)}));
  EXPECT_EQ(outside.next.root, current.root);
  EXPECT_TRUE(outside.changes.empty());
  EXPECT_EQ(outside.next.edits, current.edits + 1);
  const detail::EditResult none = build_one(current, table, ValidSet());
  EXPECT_EQ(none.next.root, current.root);
  EXPECT_TRUE(none.changes.empty());
}

// The state's limits hold for the builder: a shape over them throws LimitExceeded.
TEST(EditBuilder, AShapeOverTheLimitThrows) {
  detail::LandscapeState current = test::state_of(worn());
  current.limits.max_shape_vertices = 3;
  const detail::EditTable table = detail::EditTable::fill(7);
  EXPECT_THROW(build_one(current, table, ValidSet(PolygonSet{diamond({100, 100}, 20)})),
               LimitExceeded);
}

}  // namespace
}  // namespace edgeland
