// Save files are untrusted (issue 27, points 1-4): hostile files built field by field with the
// load fuzzer's own codec (tests/support/save_file.hpp, which shares no code with the library),
// each refused with a LoadError or LimitExceeded before the work it asks for is done, and never a
// world that fails check().
#include "save_file.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <limits>
#include <sstream>

#include "check.hpp"  // spatial/src: check_cell on a hand-made grid cell
#include "edgeland/spatial/landscape.hpp"
#include "save_mutator.hpp"

namespace edgeland::test {
namespace {

using fuzz::SavedNode;
using fuzz::SavedPolygon;
using fuzz::SaveFile;

Landscape load_bytes(const std::string& bytes, const LandscapeLimits& limits = {}) {
  std::istringstream in(bytes);
  return Landscape::load(in, limits);
}

LoadError load_error(const std::string& bytes) {
  try {
    load_bytes(bytes);
  } catch (const LoadError& e) {
    return e;
  }
  ADD_FAILURE() << "loaded";
  return LoadError("loaded", 0);
}

std::string saved(const Landscape& l) {
  std::ostringstream out;
  l.save(out);
  return out.str();
}

SavedPolygon square(std::uint64_t id, std::uint8_t material, std::int64_t x, std::int64_t y,
                    std::int64_t side) {
  return {id, material, {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}};
}

TEST(SaveFileCodec, ReadsBackWhatTheLibraryWrites) {
  Landscape l({{0, 0}, {1000, 1000}}, 1);
  for (int i = 0; i < 8; ++i)
    l.carve(PolygonSet{{{100 * i + 10, 10}, {100 * i + 60, 20}, {100 * i + 30, 70}}});
  const std::string bytes = saved(l);
  const std::optional<SaveFile> f = fuzz::decode_save(bytes);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(fuzz::encode_save(*f), bytes);
  EXPECT_EQ(f->nodes.front().polygons.size(), l.stats().cells == 1 ? l.stats().polygons : 0u);
}

// Point 1: the file, a full quadtree of empty cells, was refused only after the whole
// tree was built (0.6 MB: 117 MB and 1.1 s). Its first four leaves already break the merge rule
// (I8), and that is where it is refused now: at the first inner node whose children are read.
TEST(SaveFileHostile, AFullTreeOfEmptyCellsIsRefusedAtItsFirstLeaves) {
  const std::string bytes = fuzz::encode_save(fuzz::full_tree_of_empty_cells(9));
  ASSERT_EQ(bytes.size(), 611750u);  // the 0.6 MB
  const LoadError e = load_error(bytes);
  EXPECT_NE(std::string(e.what()).find("children small enough to merge"), std::string::npos)
      << e.what();
  // Header (73 bytes), nine inner tags on the way down, four empty cells of 2 bytes.
  EXPECT_EQ(e.offset, 73u + 9 + 4 * 2);
}

// Point 1: a count (cells, polygons, vertices) is refused by the bytes left or the limits before
// anything is allocated for it.
TEST(SaveFileHostile, CountsAndLimitsAreCheckedBeforeTheWork) {
  SaveFile f;
  f.next_id = 2;
  SavedNode cell;
  cell.polygons.push_back(square(1, 1, 0, 0, 10));
  f.nodes.push_back(cell);
  std::string bytes = fuzz::encode_save(f);
  EXPECT_NO_THROW(load_bytes(bytes));
  // More vertices than the limit allows: LimitExceeded naming the limit.
  try {
    load_bytes(bytes, LandscapeLimits{.max_vertices = 3});
    FAIL() << "loaded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kVertices);
    EXPECT_EQ(e.requested, 4u);
  }
  // More cells than the limit allows.
  SaveFile split = fuzz::full_tree_of_empty_cells(1);
  split.merge_below = 0;  // so that four empty cells are no merge to refuse
  split.edge_cap = 32;
  split.nodes[1].polygons.push_back(square(1, 1, -kCoordBound, -kCoordBound, 10));
  split.next_id = 2;
  EXPECT_NO_THROW(load_bytes(fuzz::encode_save(split)));
  try {
    load_bytes(fuzz::encode_save(split), LandscapeLimits{.max_cells = 3});
    FAIL() << "loaded";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kCells);
  }
}

// Point 2: a next id of 0 was accepted, the next edit handed out id 0, and the library's own
// save of that world then failed to load.
TEST(SaveFileHostile, ANextIdNotAboveEveryIdIsRefused) {
  SaveFile empty;
  empty.next_id = 0;
  EXPECT_NE(std::string(load_error(fuzz::encode_save(empty)).what()).find("next id 0"),
            std::string::npos);
  SaveFile f;
  SavedNode cell;
  cell.polygons.push_back(square(7, 1, 0, 0, 10));
  f.nodes.push_back(cell);
  for (const std::uint64_t next : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{7}}) {
    f.next_id = next;
    EXPECT_THROW(load_bytes(fuzz::encode_save(f)), LoadError) << next;
  }
  f.next_id = 8;
  const Landscape l = load_bytes(fuzz::encode_save(f));
  EXPECT_TRUE(l.check().ok());
}

// Point 2, the other end: a next id at the top of the range is loadable, but no edit may wrap
// it round to 0.
TEST(SaveFileHostile, UsedUpIdsStopAnEditAndChangeNothing) {
  SaveFile f;
  f.next_id = std::numeric_limits<std::uint64_t>::max();
  f.nodes.push_back(SavedNode{});
  Landscape l = load_bytes(fuzz::encode_save(f));
  const std::uint64_t before = l.state_hash();
  try {
    l.fill(PolygonSet{{{0, 0}, {10, 0}, {10, 10}}}, 1);
    FAIL() << "filled";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kPolygonIds);
  }
  EXPECT_EQ(l.state_hash(), before);
}

// Point 3: a grid-mode file (grid_depth 3) whose tree is one cell was accepted and never split;
// check() said ok.
TEST(SaveFileHostile, AGridOfTheWrongShapeIsRefusedAndCheckSaysSo) {
  SaveFile f;
  f.grid_depth = 3;
  f.nodes.push_back(SavedNode{});
  const LoadError e = load_error(fuzz::encode_save(f));
  EXPECT_NE(std::string(e.what()).find("a grid cell above the grid depth 3"), std::string::npos)
      << e.what();
  LandscapeConfig config;
  config.grid_depth = 3;
  const detail::NodePtr cell = detail::make_cell({{0, 0}, {1024, 1024}}, 0, {}, {});
  std::vector<std::string> problems;
  detail::check_cell(*cell, config, problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems.front(), "cell (0 0 1024 1024): a grid cell above the grid depth 3");
  // The grid the constructor builds is the shape load accepts.
  const Landscape grid({{0, 0}, {1024, 1024}}, 1, config);
  EXPECT_EQ(grid.stats().cells, 64u);
  EXPECT_TRUE(grid.check().ok());
  EXPECT_EQ(load_bytes(saved(grid)).state_hash(), grid.state_hash());
}

// A world whose cells hold holes (split by bridges, the cells load decides by an overlay) and
// many plain ones: load gives it back exactly, and a cell made non-canonical is refused.
TEST(SaveFileHostile, ANonCanonicalCellIsRefused) {
  Landscape l({{0, 0}, {256, 256}}, 1);
  l.carve(PolygonSet{{{100, 100}, {120, 100}, {120, 120}, {100, 120}}});  // a hole in rock
  const std::string bytes = saved(l);
  EXPECT_EQ(load_bytes(bytes).state_hash(), l.state_hash());
  SaveFile f = *fuzz::decode_save(bytes);
  ASSERT_EQ(f.nodes.size(), 1u);
  // The rock around the hole is two polygons sharing the bridges; the same region as one cell of
  // two squares side by side, same material, is not canonical (they should be one polygon).
  f.nodes[0].polygons = {square(1, 1, 0, 0, 10), square(2, 1, 10, 0, 10)};
  f.next_id = 3;
  const LoadError e = load_error(fuzz::encode_save(f));
  EXPECT_NE(std::string(e.what()).find("not the canonical decomposition"), std::string::npos)
      << e.what();
}

// Point 4 as a property: a real save, decoded, changed in one to three fields, nodes, polygons or
// vertices, and written back with a correct checksum, either loads into a world that passes
// check() and saves and loads to the same state hash, or is refused with a typed error.
RC_GTEST_PROP(SaveFileProperty, AChangedSaveIsRefusedOrAValidWorld, ()) {
  static const std::string bytes = [] {
    LandscapeConfig config;
    config.edge_cap = 32;
    config.merge_below = 10;
    Landscape l({{0, 0}, {512, 512}}, 1, config);
    for (int i = 0; i < 30; ++i) {
      const std::int64_t x = 17 * i % 480, y = 31 * i % 470;
      l.carve(PolygonSet{{{x, y}, {x + 25, y + 3}, {x + 20, y + 30}, {x + 2, y + 22}}});
      if (i % 3 == 0)
        l.fill(PolygonSet{{{x + 5, y + 5}, {x + 12, y + 6}, {x + 8, y + 14}}}, 2 + i % 4);
    }
    return saved(l);
  }();
  const std::optional<std::string> changed =
      fuzz::mutate_save(bytes, *rc::gen::arbitrary<std::uint32_t>());
  RC_ASSERT(changed.has_value());
  try {
    const Landscape l = load_bytes(*changed);
    const LandscapeReport report = l.check();
    RC_ASSERT(report.ok());
    RC_ASSERT(load_bytes(saved(l)).state_hash() == l.state_hash());
  } catch (const LoadError&) {
  } catch (const LimitExceeded&) {
  }
}

}  // namespace
}  // namespace edgeland::test
