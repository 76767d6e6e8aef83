#pragma once
// What the relabel tests (relabel_cell_test.cpp, relabel_batch_test.cpp) build their cells and
// tables from: one home for both.
#include <rapidcheck.h>

#include <cstdint>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "generators.hpp"

namespace edgeland::test {

// Every material becomes m (m = 0: carved).
inline std::vector<RegionLabel> fill_table(RegionLabel m) {
  return std::vector<RegionLabel>(256, m);
}

// A cell's content: up to four fills of random shapes of materials 1-3 into the box [0, size]^2,
// canonical as a landscape cell holds it.
inline LabeledSet random_cell_content(std::int64_t size) {
  const Box64 box{{0, 0}, {size, size}};
  LabeledSet content;
  const int fills = *rc::gen::inRange(1, 5);
  for (int i = 0; i < fills; ++i) {
    const std::int64_t r = *rc::gen::element<std::int64_t>(3, size / 4, size / 2, size);
    const Polygon p = *gen::shape(*gen::point_in({0, 0}, {size, size}), r);
    const RegionLabel m = *rc::gen::inRange<RegionLabel>(1, 4);
    content =
        relabel(content.set, content.labels, ValidSet(PolygonSet{p}), box, fill_table(m)).regions;
  }
  return content;
}

}  // namespace edgeland::test
