// The landscape's checkers (spatial/src/check.hpp) on nodes and states that break one invariant
// each (spatial/README.md, I1-I9): every check must name the broken one, and an intact node or
// state must pass. A landscape built through the public API never breaks them (that is what
// the other tests show), so the broken ones are made here by hand from the tree's own node
// constructors (node.hpp) and states made from them (check.hpp takes a state).
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "changes.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "valid_set_factory.hpp"  // clip/src

namespace edgeland::test {
namespace {

using detail::Node;
using detail::NodePtr;

Polygon square(std::int64_t x, std::int64_t y, std::int64_t side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

// A staircase of 2k + 2 vertices, every one a corner (no collinear vertex), counter-clockwise
// from (x, y): k unit steps up to (x + k, y + k - 1), then (x + k, y + top), (x, y + top);
// top >= k.
Polygon staircase(std::int64_t x, std::int64_t y, std::int64_t k, std::int64_t top) {
  Polygon p;
  for (std::int64_t i = 0; i < k; ++i) {
    p.push_back({x + i, y + i});
    p.push_back({x + i + 1, y + i});
  }
  p.push_back({x + k, y + top});
  p.push_back({x, y + top});
  return p;
}

LabeledSet labeled(PolygonSet polys, std::vector<RegionLabel> labels) {
  return {ValidSet(std::move(polys)), std::move(labels)};
}

std::vector<PolygonId> ids_from(PolygonId first, std::size_t n) {
  std::vector<PolygonId> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = first + i;
  return ids;
}

NodePtr cell(const Box64& box, std::uint32_t depth, PolygonSet polys,
             std::vector<RegionLabel> labels, PolygonId first_id = 1) {
  const std::size_t n = polys.size();
  return detail::make_cell(box, depth, labeled(std::move(polys), std::move(labels)),
                           ids_from(first_id, n));
}

std::shared_ptr<Node> copy(const NodePtr& n) { return std::make_shared<Node>(*n); }

std::vector<std::string> cell_problems(const Node& c, const LandscapeConfig& config = {}) {
  std::vector<std::string> problems;
  detail::check_cell(c, config, problems);
  return problems;
}

std::vector<std::string> inner_problems(const Node& n, const LandscapeConfig& config = {}) {
  std::vector<std::string> problems;
  detail::check_inner(n, config, problems);
  return problems;
}

bool names(const std::vector<std::string>& problems, const std::string& what) {
  for (const std::string& p : problems)
    if (p.find(what) != std::string::npos) return true;
  return false;
}

const Box64 kCell{{0, 0}, {64, 64}};

TEST(CheckCell, AnIntactCellPasses) {
  EXPECT_TRUE(cell_problems(*cell(kCell, 0, {square(0, 0, 8), square(20, 20, 8)}, {1, 2})).empty());
  EXPECT_TRUE(cell_problems(*cell(kCell, 0, {}, {})).empty());
}

TEST(CheckCell, ArraysOfDifferentLengths) {
  const NodePtr intact = cell(kCell, 0, {square(0, 0, 8), square(20, 20, 8)}, {1, 2});
  for (int shortened = 0; shortened < 3; ++shortened) {
    auto c = copy(intact);
    if (shortened == 0) c->content.labels.pop_back();
    if (shortened == 1) c->ids.pop_back();
    if (shortened == 2) c->boxes.pop_back();
    const auto problems = cell_problems(*c);
    ASSERT_EQ(problems.size(), 1u) << shortened;
    EXPECT_TRUE(names(problems, "cell (0 0 64 64): labels, ids or boxes do not match"));
  }
}

// I1: a set that is not valid (two overlapping squares), as only a bug or broken memory could
// put in a cell: ValidSetFactory is the clipper's door for sets it vouches for unchecked.
TEST(CheckCell, AnInvalidSet) {
  ClipResult overlapping;
  overlapping.polygons = {square(0, 0, 8), square(4, 4, 8)};
  const NodePtr c = detail::make_cell(
      kCell, 0, {ValidSetFactory::from(std::move(overlapping)).set, {1, 2}}, {1, 2});
  const auto problems = cell_problems(*c);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "cell (0 0 64 64): invalid: overlapping-interiors"));
}

TEST(CheckCell, AStoredBoxThatIsNotThePolygons) {
  auto c = copy(cell(kCell, 0, {square(0, 0, 8)}, {1}));
  c->boxes[0].max.x = 9;
  const auto problems = cell_problems(*c);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "polygon 0 has a wrong box"));
}

TEST(CheckCell, APolygonOutsideItsCell) {  // I2
  const auto problems = cell_problems(*cell({{0, 0}, {16, 16}}, 0, {square(10, 10, 8)}, {1}));
  EXPECT_TRUE(names(problems, "polygon 0 outside the cell"));
}

TEST(CheckCell, MaterialsOutsideOneTo255) {
  EXPECT_TRUE(names(cell_problems(*cell(kCell, 0, {square(0, 0, 8)}, {0})), "has material 0"));
  EXPECT_TRUE(names(cell_problems(*cell(kCell, 0, {square(0, 0, 8)}, {256})), "has material 256"));
}

// I5: more edges than the cap in a cell that may split; a cell at min_cell_size may hold any
// number.
TEST(CheckCell, OverTheEdgeCapOnlyWhereASplitIsAllowed) {
  const LandscapeConfig config{.edge_cap = 32, .merge_below = 8, .min_cell_size = 16};
  const Polygon many = staircase(0, 0, 16, 16);  // 34 vertices in the 16 x 16 corner
  EXPECT_TRUE(names(cell_problems(*cell(kCell, 0, {many}, {1}), config), "34 edges, over the cap"));
  EXPECT_FALSE(names(cell_problems(*cell({{0, 0}, {16, 16}}, 2, {many}, {1}), config), "over"));
}

// I9: in grid mode every cell that may split lies at the grid depth.
TEST(CheckCell, AGridCellAboveTheGridDepth) {
  const LandscapeConfig grid{.grid_depth = 2};
  EXPECT_TRUE(names(cell_problems(*cell(kCell, 1, {}, {}), grid), "above the grid depth 2"));
  EXPECT_TRUE(cell_problems(*cell(kCell, 2, {}, {}), grid).empty());
  // A cell too small to split may end the grid early.
  EXPECT_TRUE(cell_problems(*cell({{0, 0}, {16, 16}}, 1, {}, {}), grid).empty());
}

// I3: two squares of one material sharing a side are one region, whose canonical
// decomposition is one polygon.
TEST(CheckCell, ContentThatIsNotTheCanonicalDecomposition) {
  const auto problems = cell_problems(*cell(kCell, 0, {square(0, 0, 8), square(8, 0, 8)}, {1, 1}));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "not the canonical decomposition"));
  // Of two materials they are two regions: canonical as they are.
  EXPECT_TRUE(cell_problems(*cell(kCell, 0, {square(0, 0, 8), square(8, 0, 8)}, {1, 2})).empty());
}

// Polygons too large for the pairwise test (70 x 70 edge pairs, over 4096) are left to the
// overlay, which finds two apart canonical and two sharing a side (one region) not.
TEST(CheckCell, LargePolygonsAreJudgedByTheOverlay) {
  const LandscapeConfig roomy{.edge_cap = 1000, .merge_below = 8};
  const Box64 tall{{0, 0}, {64, 160}};
  const Polygon below = staircase(0, 0, 34, 40);  // 70 vertices
  Polygon apart;
  for (const Point64& p : below) apart.push_back({p.x, p.y + 100});
  EXPECT_TRUE(cell_problems(*cell(tall, 0, {below, apart}, {1, 1}), roomy).empty());
  // Mirrored across y = 40 (turned back to counter-clockwise, from its least vertex (0, 40)):
  // it shares the side from (0, 40) to (34, 40).
  Polygon above;
  for (auto it = below.rbegin(); it != below.rend(); ++it) above.push_back({it->x, 80 - it->y});
  std::rotate(above.begin(), std::min_element(above.begin(), above.end()), above.end());
  EXPECT_TRUE(names(cell_problems(*cell(tall, 0, {below, above}, {1, 1}), roomy),
                    "not the canonical decomposition"));
}

TEST(CheckCell, StoredSumsThatDifferFromTheContent) {
  auto c = copy(cell(kCell, 0, {square(0, 0, 8)}, {1}));
  c->hash ^= 1;
  const auto problems = cell_problems(*c);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "stored sums or hash differ"));
}

// --- inner nodes (I4, I7, I8, the grid) -------------------------------------------------------

// The four quadrants of kCell (split_boxes order: x before y, low before high).
std::vector<NodePtr> quadrants(std::uint32_t depth, std::vector<PolygonSet> contents) {
  const Box64 boxes[4] = {
      {{0, 0}, {32, 32}}, {{32, 0}, {64, 32}}, {{0, 32}, {32, 64}}, {{32, 32}, {64, 64}}};
  std::vector<NodePtr> out;
  PolygonId id = 1;
  for (std::size_t i = 0; i < 4; ++i) {
    std::vector<RegionLabel> labels(contents[i].size(), 1);
    const std::size_t n = contents[i].size();
    out.push_back(cell(boxes[i], depth, std::move(contents[i]), std::move(labels), id));
    id += n;
  }
  return out;
}

// 44 vertices in all: above merge_below (24), so an adaptive tree keeps the split.
std::vector<PolygonSet> busy() {
  return {{staircase(2, 2, 10, 12)}, {staircase(34, 2, 10, 12)}, {}, {}};
}

TEST(CheckInner, AnIntactNodePasses) {
  EXPECT_TRUE(inner_problems(*detail::make_inner(kCell, 0, quadrants(1, busy()))).empty());
}

TEST(CheckInner, ANodeTooSmallToSplit) {
  const LandscapeConfig config{.min_cell_size = 64};
  const auto problems = inner_problems(*detail::make_inner(kCell, 0, quadrants(1, busy())), config);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "node (0 0 64 64): split although it may not"));
}

TEST(CheckInner, TheWrongNumberOfChildren) {
  std::vector<NodePtr> two = quadrants(1, busy());
  two.resize(2);
  const auto problems = inner_problems(*detail::make_inner(kCell, 0, two));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "wrong number of children"));
}

TEST(CheckInner, AChildThatIsNotItsPartOfTheBox) {
  std::vector<NodePtr> children = quadrants(1, busy());
  std::swap(children[2], children[3]);
  EXPECT_TRUE(names(inner_problems(*detail::make_inner(kCell, 0, children)),
                    "child 2 is not its part of the box"));
  // A child one level too deep.
  children = quadrants(2, busy());
  EXPECT_TRUE(names(inner_problems(*detail::make_inner(kCell, 0, children)), "child 0"));
  // A missing child stops the check there.
  auto node = copy(detail::make_inner(kCell, 0, quadrants(1, busy())));
  node->children[1].reset();
  const auto problems = inner_problems(*node);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(names(problems, "child 1 is not its part of the box"));
}

// I8: cells together at most merge_below edges must have been merged.
TEST(CheckInner, ChildrenSmallEnoughToMerge) {
  const auto few = quadrants(1, {{square(2, 2, 8)}, {}, {}, {}});
  EXPECT_TRUE(
      names(inner_problems(*detail::make_inner(kCell, 0, few)), "children small enough to merge"));
  // Not in grid mode, where nothing merges.
  EXPECT_FALSE(
      names(inner_problems(*detail::make_inner(kCell, 0, few), {.grid_depth = 1}), "merge"));
}

TEST(CheckInner, AGridNodeBelowTheGridDepth) {
  const auto problems =
      inner_problems(*detail::make_inner(kCell, 1, quadrants(2, busy())), {.grid_depth = 1});
  EXPECT_TRUE(names(problems, "grid node below the grid depth"));
}

// I7: every sum and every field of the cut a node keeps is compared with its children's.
TEST(CheckInner, StoredSumsThatDifferFromTheChildren) {
  const NodePtr intact = detail::make_inner(kCell, 0, quadrants(1, busy()));
  const std::vector<void (*)(Node&)> breaks{
      [](Node& n) { n.polygons += 1; },    [](Node& n) { n.vertices += 1; },
      [](Node& n) { n.cells += 1; },       [](Node& n) { n.deepest += 1; },
      [](Node& n) { n.hash ^= 1; },        [](Node& n) { n.cut_x = !n.cut_x; },
      [](Node& n) { n.cut_y = !n.cut_y; }, [](Node& n) { n.x_line -= 1; },
      [](Node& n) { n.y_line -= 1; }};
  for (std::size_t k = 0; k < breaks.size(); ++k) {
    auto node = copy(intact);
    breaks[k](*node);
    const auto problems = inner_problems(*node);
    ASSERT_EQ(problems.size(), 1u) << k;
    EXPECT_TRUE(names(problems, "node (0 0 64 64): stored sums or hash differ")) << k;
  }
}

// --- what an edit made (check_edit) and a whole landscape (check_all) --------------------------

// The areas a landscape keeps, summed over the cells of a tree that may be broken: missing
// children and labels past the arrays or the materials add nothing.
void add_areas(const NodePtr& n, detail::AreaTable& areas) {
  if (!n) return;
  for (std::uint32_t i = 0; i < n->child_count; ++i) add_areas(n->children[i], areas);
  for (std::size_t i = 0; i < n->polygons && i < n->content.labels.size(); ++i)
    if (n->content.labels[i] < kMaterialCount)
      areas[n->content.labels[i]] += twice_signed_area(n->polygon_set()[i]);
}

// A landscape's state over kCell made of the given root (as a load makes one).
detail::LandscapeState landscape_of(NodePtr root, PolygonId next_id) {
  detail::LandscapeState s;
  s.world = kCell;
  s.root = std::move(root);
  auto areas = std::make_shared<detail::AreaTable>();
  add_areas(s.root, *areas);
  s.areas = std::move(areas);
  s.next_id = next_id;
  return s;
}

TEST(CheckEdit, ATreeWhoseRootIsNotTheWorld) {
  const NodePtr before = cell(kCell, 0, {square(0, 0, 8)}, {1});
  const detail::LandscapeState l = landscape_of(before, 2);
  const NodePtr elsewhere = cell({{0, 0}, {32, 32}}, 0, {square(0, 0, 8)}, {1});
  EXPECT_EQ(detail::check_edit(l, elsewhere, {{before}, {elsewhere}, {}}, 2),
            "the root is not the world");
  const NodePtr deeper = cell(kCell, 1, {square(0, 0, 8)}, {1});
  EXPECT_EQ(detail::check_edit(l, deeper, {{before}, {deeper}, {}}, 2),
            "the root is not the world");
  EXPECT_EQ(detail::check_edit(l, before, {{before}, {before}, {}}, 2), "");
}

NodePtr cell_with_ids(PolygonSet polys, std::vector<PolygonId> ids) {
  std::vector<RegionLabel> labels(polys.size(), 1);
  return detail::make_cell(kCell, 0, labeled(std::move(polys), std::move(labels)), std::move(ids));
}

TEST(CheckEdit, IdsGivenTwiceOrTakenFromAPolygonThatStays) {
  const NodePtr before = cell(kCell, 0, {square(0, 0, 8), square(20, 0, 8)}, {1, 1}, 1);
  const detail::LandscapeState l = landscape_of(before, 3);
  // The edit's new cell gives id 1 to both its polygons.
  const NodePtr twice = cell_with_ids({square(0, 0, 8), square(40, 0, 8)}, {1, 1});
  EXPECT_EQ(detail::check_edit(l, twice, {{before}, {twice}, {}}, 3), "id 1 twice");
  // Id 2 belongs to a polygon of an old cell the edit did not replace.
  const NodePtr taken = cell_with_ids({square(40, 0, 8)}, {2});
  EXPECT_EQ(detail::check_edit(l, taken, {{}, {taken}, {}}, 3),
            "id 2 taken from a polygon that stays");
  // Several problems: the first, and how many more.
  EXPECT_EQ(detail::check_edit(l, twice, {{}, {twice}, {}}, 3),
            "id 1 taken from a polygon that stays (and 2 more)");
  // Ids of the replaced cells and fresh ones (at or above the old next id) are fine.
  const NodePtr renumbered = cell_with_ids({square(0, 0, 8), square(40, 0, 8)}, {1, 3});
  EXPECT_EQ(detail::check_edit(l, renumbered, {{before}, {renumbered}, {}}, 3), "");
}

TEST(CheckAll, AnIntactLandscapePasses) {
  EXPECT_TRUE(
      detail::check_all(landscape_of(detail::make_inner(kCell, 0, quadrants(1, busy())), 3)).ok());
}

TEST(CheckAll, TheRootIsNotTheWorld) {
  EXPECT_TRUE(names(detail::check_all(landscape_of(cell(kCell, 1, {}, {}), 1)).problems,
                    "the root is not the world"));
  EXPECT_TRUE(
      names(detail::check_all(landscape_of(cell({{0, 0}, {32, 64}}, 0, {}, {}), 1)).problems,
            "the root is not the world"));
}

TEST(CheckAll, AnIdNotBelowTheNextId) {
  const detail::LandscapeState l =
      landscape_of(cell(kCell, 0, {square(0, 0, 8), square(20, 0, 8)}, {1, 2}), 2);
  const LandscapeReport r = detail::check_all(l);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_EQ(r.problems.front(), "an id is not below the next id");
}

TEST(CheckAll, AnIdInTwoCells) {
  std::vector<NodePtr> children = quadrants(1, busy());
  auto second = copy(children[1]);
  second->ids = {1};  // the first cell's id
  second->hash = detail::make_cell(second->box, 1, second->content, second->ids)->hash;
  children[1] = second;
  const LandscapeReport r =
      detail::check_all(landscape_of(detail::make_inner(kCell, 0, children), 3));
  EXPECT_TRUE(names(r.problems, "id 1 twice"));
}

TEST(CheckAll, AnAreaThatIsNotTheSumOfItsPolygons) {
  detail::LandscapeState s = landscape_of(cell(kCell, 0, {square(0, 0, 8)}, {3}), 2);
  auto areas = std::make_shared<detail::AreaTable>(*s.areas);
  (*areas)[3] += 2;
  s.areas = std::move(areas);
  const LandscapeReport r = detail::check_all(s);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_EQ(r.problems.front(), "the area of material 3 is not the sum of its polygons");
}

// A broken cell is reported by check() with its box, and its material is not counted (a label
// past 255 has no area entry).
TEST(CheckAll, ABrokenCellIsNamed) {
  const LandscapeReport r =
      detail::check_all(landscape_of(cell(kCell, 0, {square(0, 0, 8)}, {300}), 2));
  EXPECT_TRUE(names(r.problems, "cell (0 0 64 64): polygon 0 has material 300"));
}

// Whole-landscape checks go on past a broken node: a missing child and a cell whose arrays
// differ in length are reported, and the rest of the tree is still checked.
TEST(CheckAll, AMissingChildAndShortArraysAreReported) {
  std::vector<NodePtr> children = quadrants(1, busy());
  auto short_labels = copy(children[0]);
  short_labels->content.labels.clear();
  children[0] = short_labels;
  auto root = copy(detail::make_inner(kCell, 0, children));
  root->children[3].reset();
  const LandscapeReport r = detail::check_all(landscape_of(root, 3));
  EXPECT_TRUE(names(r.problems, "cell (0 0 32 32): labels, ids or boxes do not match"));
  EXPECT_TRUE(names(r.problems, "node (0 0 64 64): child 3 is not its part of the box"));
}

}  // namespace
}  // namespace edgeland::test
