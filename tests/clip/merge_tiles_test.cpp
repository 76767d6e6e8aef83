// merge_tiles (clip.hpp): a valid set cut into tiles the way a landscape cuts it (boxes of a
// random quadtree, so a big tile's edge meets several small ones: T-junctions on the cut lines)
// is merged back without the general pipeline. Checked against merge() of the same tiles: the
// same region (their xor is empty), a valid canonical result, the exact area of the tiles.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <memory>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/canonical_form.hpp"
#include "generators.hpp"

namespace edgeland::test {
namespace {

// The boxes of a quadtree over `box` whose leaves split on a coin (down to 4 units).
void quadtree_leaves(const Box64& box, std::vector<Box64>& out) {
  const std::int64_t w = box.max.x - box.min.x;
  if (w <= 4 || *rc::gen::inRange(0, 3) == 0) {
    out.push_back(box);
    return;
  }
  const Point64 m{box.min.x + w / 2, box.min.y + (box.max.y - box.min.y) / 2};
  quadtree_leaves({box.min, m}, out);
  quadtree_leaves({{m.x, box.min.y}, {box.max.x, m.y}}, out);
  quadtree_leaves({{box.min.x, m.y}, {m.x, box.max.y}}, out);
  quadtree_leaves({m, box.max}, out);
}

// The set cut at the leaves' boxes: each leaf's part as tiles, together a valid set.
ValidSet tiles_of(const ValidSet& set, const std::vector<Box64>& leaves) {
  PolygonSet tiles;
  for (const Box64& leaf : leaves) {
    const ValidClipResult part = clip_to_box(set, leaf, {.checked = true});
    tiles.insert(tiles.end(), part.set.polygons().begin(), part.set.polygons().end());
  }
  return ValidSet(std::move(tiles));
}

void expect_same_region(const ValidSet& tiles) {
  const ValidClipResult fast = merge_tiles(tiles, {.checked = true});
  const ValidClipResult slow = merge(tiles, {.checked = true});
  RC_ASSERT(validate(fast.set.polygons()).ok());
  RC_ASSERT(is_canonical(fast.set.polygons()));
  RC_ASSERT(twice_signed_area(fast.set.polygons()) == twice_signed_area(tiles.polygons()));
  RC_ASSERT(clip(ClipOp::kXor, fast.set, slow.set).set.polygons().empty());
  RC_ASSERT(fast.set.polygons().size() <= tiles.polygons().size());
}

// A random valid set cut at the boxes of a random quadtree over it.
ValidSet random_tiles() {
  const PolygonSet raw = *gen::polygon_set({64, 64}, 60);
  const ValidSet set =
      normalize_to_valid_set(std::vector<Ring>(raw.begin(), raw.end()), FillRule::kPositive).set;
  std::vector<Box64> leaves;
  quadtree_leaves({{0, 0}, {128, 128}}, leaves);
  return tiles_of(set, leaves);
}

RC_GTEST_PROP(MergeTiles, QuadtreeTilesMergeToMergesRegion, ()) {
  expect_same_region(random_tiles());
}

// TileMerge keeps what it needs: finished after the tiles are gone (a frame later, in a game),
// with checked mode's area check against the tiles it was given, it gives merge_tiles' result.
RC_GTEST_PROP(MergeTiles, ATileMergeFinishedLaterIsMergeTiles, ()) {
  auto tiles = std::make_unique<ValidSet>(random_tiles());
  const ValidClipResult whole = merge_tiles(*tiles, {.checked = true});
  TileMerge started(*tiles, {.checked = true});
  tiles.reset();
  const ValidClipResult finished = std::move(started).finish();
  RC_ASSERT(finished.set.polygons() == whole.set.polygons());
  RC_ASSERT(finished.stats.holes_split == whole.stats.holes_split);
}

PolygonSet squares(std::initializer_list<Box64> boxes) {
  PolygonSet out;
  for (const Box64& b : boxes)
    out.push_back({b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}});
  return out;
}

// A big square beside two small ones: the big one's side meets both at a T-junction.
TEST(MergeTiles, TJunctionsOnACutLineMergeToOneSquare) {
  const ValidSet tiles(squares({{{0, 0}, {4, 4}}, {{4, 0}, {6, 2}}, {{4, 2}, {6, 4}}}));
  const PolygonSet merged = merge_tiles(tiles, {.checked = true}).set.polygons();
  EXPECT_EQ(merged, squares({{{0, 0}, {6, 4}}}));
}

// A ring of eight tiles around an empty middle: one region with a hole, split into hole-free
// polygons as merge() splits it.
TEST(MergeTiles, ARingOfTilesKeepsItsHole) {
  PolygonSet ring;
  for (std::int64_t i = 0; i < 3; ++i)
    for (std::int64_t j = 0; j < 3; ++j)
      if (i != 1 || j != 1) ring.push_back(squares({{{2 * i, 2 * j}, {2 * i + 2, 2 * j + 2}}})[0]);
  const ValidSet tiles(std::move(ring));
  const ValidClipResult fast = merge_tiles(tiles, {.checked = true});
  EXPECT_EQ(fast.stats.holes_split, 1u);
  EXPECT_EQ(twice_signed_area(fast.set.polygons()), Int128(2 * 32));
  EXPECT_TRUE(clip(ClipOp::kXor, fast.set, merge(tiles).set).set.polygons().empty());
}

// Two squares meeting at one corner only stay two polygons (a pinch is no shared stretch).
TEST(MergeTiles, TilesMeetingAtAPointStayApart) {
  const ValidSet tiles(squares({{{0, 0}, {2, 2}}, {{2, 2}, {4, 4}}}));
  EXPECT_EQ(merge_tiles(tiles, {.checked = true}).set.polygons(), tiles.polygons());
}

// A triangle's corner on a square's side (not a vertex of it): touching at a point, apart.
TEST(MergeTiles, ACornerOnAnotherTilesSideStaysApart) {
  const ValidSet tiles(PolygonSet{{{0, 0}, {4, 0}, {4, 2}, {0, 2}}, {{2, 2}, {4, 5}, {0, 5}}});
  const ValidClipResult fast = merge_tiles(tiles, {.checked = true});
  EXPECT_EQ(fast.set.polygons().size(), 2u);
  EXPECT_TRUE(clip(ClipOp::kXor, fast.set, tiles).set.polygons().empty());
}

// Two members sharing a stretch and touching at a second point, where one's corner lies inside
// the other's side (off its line): their union encloses a hole that touches the outside there.
// The island of a game's property case (GameDriverProperty.NoIslandWaitsLongerThanItsLimit):
// without the stretch split at that corner, the traced ring touched its own edge (invalid).
TEST(MergeTiles, ACornerInsideASideClosingAHoleIsSplitThere) {
  const ValidSet tiles(PolygonSet{{{-300, -298},
                                   {-299, -298},
                                   {-299, -300},
                                   {-298, -299},
                                   {-296, -299},
                                   {-296, -297},
                                   {-284, -285},
                                   {-295, -300},
                                   {-292, -299},
                                   {-274, -276},
                                   {-297, -295},
                                   {-299, -291}},
                                  {{-296, -298}, {-284, -285}, {-286, -287}}});
  const ValidClipResult fast = merge_tiles(tiles, {.checked = true});
  EXPECT_TRUE(validate(fast.set.polygons()).ok());
  EXPECT_TRUE(is_canonical(fast.set.polygons()));
  EXPECT_EQ(twice_signed_area(fast.set.polygons()), twice_signed_area(tiles.polygons()));
  EXPECT_TRUE(clip(ClipOp::kXor, fast.set, merge(tiles).set).set.polygons().empty());
}

TEST(MergeTiles, EmptySetMergesToEmpty) {
  EXPECT_TRUE(merge_tiles(ValidSet(PolygonSet{})).set.polygons().empty());
}

}  // namespace
}  // namespace edgeland::test
