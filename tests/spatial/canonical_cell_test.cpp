// I3 decided without an overlay where that is sound (spatial/src/canonical_cell.hpp), against the
// overlay itself: on every cell of worlds made by edits (canonical, by construction) and on
// cells changed to break I3 in the two ways it can break (two pieces of one material that should
// be one polygon; a ring not in canonical form), both must give the same verdict.
#include "canonical_cell.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "state_of.hpp"

namespace edgeland::test {
namespace {

std::uint64_t next(std::uint64_t& s) { return mix64(s += kSplitMix64Gamma); }

// Carves, fills and replaces of small quadrilaterals: caves (holes split by bridges) and layers.
Landscape edited_world(std::uint64_t seed) {
  Landscape l({{0, 0}, {1024, 1024}}, 1);
  for (int i = 0; i < 120; ++i) {
    const auto x = static_cast<std::int64_t>(next(seed) % 980),
               y = static_cast<std::int64_t>(next(seed) % 980);
    const auto r = 5 + static_cast<std::int64_t>(next(seed) % 30);
    const PolygonSet shape{{{x, y}, {x + r, y + 2}, {x + r + 3, y + r}, {x + 1, y + r - 2}}};
    switch (next(seed) % 4) {
      case 0:
        l.fill(shape, 2 + next(seed) % 3);
        break;
      case 1:
        l.replace(shape, 1, 5);
        break;
      default:
        l.carve(shape);
        break;
    }
  }
  return l;
}

std::vector<detail::NodePtr> cells_of(const Landscape& l) {
  std::vector<detail::NodePtr> cells;
  detail::for_each_cell(state_of(l).root, [&](const detail::NodePtr& c) { cells.push_back(c); });
  return cells;
}

detail::NodePtr with_labels(const detail::Node& c, std::vector<RegionLabel> labels) {
  return detail::make_cell(c.box, c.depth, LabeledSet{c.content.set, std::move(labels)}, c.ids);
}

TEST(CanonicalCell, AgreesWithTheOverlayOnEditedWorlds) {
  std::size_t cells = 0, merged_pairs = 0, rotated = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Landscape l = edited_world(seed);
    for (const detail::NodePtr& c : cells_of(l)) {
      ++cells;
      ASSERT_TRUE(detail::cell_is_canonical(*c));
      ASSERT_TRUE(detail::cell_is_canonical_by_overlay(*c));
      // Two polygons of different materials that share a boundary, made one material: the
      // pair should then be one polygon, so the cell is not canonical (the fast path must
      // hand such a cell to the overlay, not accept it).
      const PolygonSet& polys = c->polygon_set();
      for (std::size_t i = 0; i < polys.size(); ++i) {
        for (std::size_t j = i + 1; j < polys.size(); ++j) {
          if (c->content.labels[i] == c->content.labels[j]) continue;
          std::vector<RegionLabel> labels = c->content.labels;
          labels[j] = labels[i];
          const detail::NodePtr changed = with_labels(*c, labels);
          const bool overlay = detail::cell_is_canonical_by_overlay(*changed);
          ASSERT_EQ(detail::cell_is_canonical(*changed), overlay) << "cell " << cells;
          merged_pairs += overlay ? 0 : 1;
        }
      }
      // A ring that does not start at its smallest vertex.
      if (!polys.empty() && polys.front().size() > 3) {
        PolygonSet turned = polys;
        std::rotate(turned.front().begin(), turned.front().begin() + 1, turned.front().end());
        const detail::NodePtr changed = detail::make_cell(
            c->box, c->depth, LabeledSet{ValidSet(turned), c->content.labels}, c->ids);
        ASSERT_FALSE(detail::cell_is_canonical(*changed));
        ASSERT_FALSE(detail::cell_is_canonical_by_overlay(*changed));
        ++rotated;
      }
    }
  }
  // The worlds hold enough of each case for the comparison to mean something.
  EXPECT_GT(cells, 300u);
  EXPECT_GT(merged_pairs, 100u);
  EXPECT_GT(rotated, 100u);
}

}  // namespace
}  // namespace edgeland::test
