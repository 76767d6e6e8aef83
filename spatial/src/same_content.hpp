#pragma once
// Whether two labeled sets are the same content: equal polygons (in their canonical order) with
// equal labels. The cell overlay and the split's checked mode ask it.
#include "edgeland/clip/relabel.hpp"

namespace edgeland::detail {

inline bool same_content(const LabeledSet& a, const LabeledSet& b) {
  return a.labels == b.labels && a.set.polygons() == b.set.polygons();
}

}  // namespace edgeland::detail
