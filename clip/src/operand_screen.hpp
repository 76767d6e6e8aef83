#pragma once
// The O(n) part of checking an operand of the validating clip(): the rules of kernel
// validate.hpp that one pass over each ring decides. The rest (strict simplicity, disjoint
// interiors) is decided by the pipeline itself (clip/README.md, "Validating while clipping").
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// Every ring has at least 3 vertices, all in range, no two consecutive equal, and turns
// counter-clockwise at its lexicographically smallest vertex. For a strictly simple ring the
// last is the same as being counter-clockwise with positive area: the smallest vertex is a
// convex corner (both neighbours lie on one side of the vertical line through it, and not on
// one ray from it unless the ring folds back there).
// False exactly when validate() would report one of those rules for some ring, or the ring
// is not strictly simple (then validate() reports that).
bool rings_pass_screen(const PolygonSet& set);

}  // namespace edgeland::detail
