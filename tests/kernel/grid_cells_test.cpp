// grid_cells.hpp: exact grid sizing over the full coordinate range, against cpp_int.
#include "edgeland/kernel/grid_cells.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "exact_reference.hpp"
#include "random_geometry.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

cpp_int ceil_div(const cpp_int& a, const cpp_int& b) { return (a + b - 1) / b; }

TEST(GridCells, FullRangeBoxNeedsMoreThan64Bits) {
  // The full range holds (2B + 1)^2 = (2^32 - 1)^2 points: just below 2^64, and the cell areas
  // compared with it exceed 2^64.
  const Box64 all{{-B, -B}, {B, B}};
  const cpp_int side = cpp_int(2) * B + 1;
  EXPECT_EQ(big(point_count(all)), side * side);
  EXPECT_EQ(big(cells_covering(all, 1)), side * side);
  EXPECT_EQ(cells_covering(all, std::int64_t{1} << 32), 1);
  EXPECT_EQ(cells_covering(all, std::int64_t{1} << 31), 4);  // 2^32 - 1 points: two columns
  EXPECT_EQ(big(cells_area(std::int64_t{1} << 33, std::uint64_t{1} << 40)), cpp_int(1) << 106);
  EXPECT_EQ(big(block_size(kMaxGridSide, kMaxGridSide)), cpp_int(1) << 80);
  EXPECT_EQ(point_count(Box64{{7, -3}, {7, -3}}), 1);
}

RC_GTEST_PROP(GridCellsProperty, MatchCeilingDivisionsOfTheBox, ()) {
  const Grid g = gen_grid();
  const Point64 a = gen_point(g), b = gen_point(g);
  const Box64 box{{std::min(a.x, b.x), std::min(a.y, b.y)},
                  {std::max(a.x, b.x), std::max(a.y, b.y)}};
  const std::int64_t side =
      *rc::gen::element<std::int64_t>(1, 2, 3, 1000, std::int64_t{1} << 33, kMaxGridSide);
  const std::uint64_t n = *rc::gen::inRange<std::uint64_t>(0, std::uint64_t{1} << 40);
  const cpp_int w = cpp_int(box.max.x) - box.min.x + 1, h = cpp_int(box.max.y) - box.min.y + 1;
  RC_ASSERT(big(point_count(box)) == w * h);
  RC_ASSERT(big(cells_covering(box, side)) == ceil_div(w, side) * ceil_div(h, side));
  RC_ASSERT(big(cells_area(side, n)) == cpp_int(side) * side * n);
}

}  // namespace
}  // namespace edgeland::test
