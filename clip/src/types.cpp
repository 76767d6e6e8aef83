// The names of the clipper's enumerations (types.hpp), as the CLI and logs spell them.
#include "edgeland/clip/types.hpp"

namespace edgeland {

const char* op_name(ClipOp op) noexcept {
  switch (op) {
    case ClipOp::kUnion:
      return "union";
    case ClipOp::kIntersection:
      return "intersection";
    case ClipOp::kDifference:
      return "difference";
    case ClipOp::kXor:
      return "xor";
  }
  return "?";  // Not reached by tests: the switch covers every ClipOp.
}

const char* fill_rule_name(FillRule rule) noexcept {
  switch (rule) {
    case FillRule::kEvenOdd:
      return "evenodd";
    case FillRule::kNonZero:
      return "nonzero";
    case FillRule::kPositive:
      return "positive";
    case FillRule::kNegative:
      return "negative";
  }
  return "?";  // Not reached by tests: the switch covers every FillRule.
}

}  // namespace edgeland
