#include "edgeland/kernel/grid_cells.hpp"

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

W width(const Box64& b) { return formulas::extent<W>(b.min.x, b.max.x); }
W height(const Box64& b) { return formulas::extent<W>(b.min.y, b.max.y); }

}  // namespace

Int128 point_count(const Box64& b) noexcept {
  return formulas::block_size<W>(width(b), height(b)).v;
}

Int128 cells_covering(const Box64& b, std::int64_t side) noexcept {
  return formulas::cells_covering<W>(width(b), height(b), side).v;
}

Int128 cells_area(std::int64_t side, std::uint64_t n) noexcept {
  return formulas::cells_area<W>(side, static_cast<Int128>(n)).v;
}

Int128 block_size(std::int64_t columns, std::int64_t rows) noexcept {
  return formulas::block_size<W>(columns, rows).v;
}

}  // namespace edgeland
