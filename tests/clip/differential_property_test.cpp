// Differential properties: on generated valid inputs (tests/support/generators.hpp) every
// operation's output is valid and meets the accuracy contract of clip.hpp against the exact
// CGAL result (tests/support/accuracy_contract.hpp). Case counts: RC_PARAMS="max_success=N".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "generators.hpp"

namespace edgeland::test {
namespace {

void check_against_exact(ClipOp op) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const Outcome o = run_clip(op, p.a, p.b);
  if (!o.ok()) RC_FAIL(o.error);
  const ContractReport r = check_clip(op, p.a, p.b, *o.result);
  if (!r.ok()) RC_FAIL(r.failure);
}

RC_GTEST_PROP(ClipDifferential, UnionMeetsTheAccuracyContract, ()) {
  check_against_exact(ClipOp::kUnion);
}
RC_GTEST_PROP(ClipDifferential, IntersectionMeetsTheAccuracyContract, ()) {
  check_against_exact(ClipOp::kIntersection);
}
RC_GTEST_PROP(ClipDifferential, DifferenceMeetsTheAccuracyContract, ()) {
  check_against_exact(ClipOp::kDifference);
}
RC_GTEST_PROP(ClipDifferential, XorMeetsTheAccuracyContract, ()) {
  check_against_exact(ClipOp::kXor);
}

// clip_to_box is a fast path with the same guarantee: the contract against set AND box.
RC_GTEST_PROP(ClipDifferential, ClipToBoxMeetsTheAccuracyContract, ()) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const auto box = bounding_box(p.a);
  RC_PRE(box.has_value());
  const std::int64_t w = box->max.x - box->min.x, h = box->max.y - box->min.y;
  auto at = [](std::int64_t lo, std::int64_t len, int k) {
    return lo + static_cast<std::int64_t>(static_cast<Int128>(len) * k / 8);
  };
  const int x0 = static_cast<int>(*gen::coord(-1, 7)), y0 = static_cast<int>(*gen::coord(-1, 7));
  const int x1 = static_cast<int>(*gen::coord(x0 + 1, 9));
  const int y1 = static_cast<int>(*gen::coord(y0 + 1, 9));
  Box64 cell{{at(box->min.x, w, x0), at(box->min.y, h, y0)},
             {at(box->min.x, w, x1), at(box->min.y, h, y1)}};
  cell.min = {std::max(cell.min.x, -kCoordBound), std::max(cell.min.y, -kCoordBound)};
  cell.max = {std::min(cell.max.x, kCoordBound), std::min(cell.max.y, kCoordBound)};
  RC_PRE(cell.min.x < cell.max.x && cell.min.y < cell.max.y);
  const Outcome o = run_clip_to_box(p.a, cell);
  if (!o.ok()) RC_FAIL(o.error);
  std::vector<Point64> inputs = all_vertices(p.a);
  inputs.push_back(cell.min);
  inputs.push_back(cell.max);
  const ContractReport r =
      check_contract(exact_clip_to_box(p.a, cell), *o.result, inputs,
                     "clip_to_box box = (" + std::to_string(cell.min.x) + ' ' +
                         std::to_string(cell.min.y) + ", " + std::to_string(cell.max.x) + ' ' +
                         std::to_string(cell.max.y) + ")\n  A = " + to_wkt(p.a));
  if (!r.ok()) RC_FAIL(r.failure);
}

}  // namespace
}  // namespace edgeland::test
