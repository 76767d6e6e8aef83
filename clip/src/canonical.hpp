#pragma once
// Canonical form of a result: no collinear consecutive vertices, each ring starting at its
// smallest vertex, rings sorted. Makes equal results byte-identical.
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// `ring` must be simple with nonzero area. O(n).
Ring canonical_ring(Ring ring);
// O(total n + p log p).
void canonicalize(PolygonSet& set);

}  // namespace edgeland::detail
