#pragma once
// What every query accepts (spatial/README.md, "Queries"): the one rule is the edits' rule,
// every coordinate within the bound; a point, a segment end or a box corner beyond it throws
// CoordinateOutOfRange (operand kQuery, `vertex` the argument's index, the message its name).
// An inverted box is no error: it holds no point.
#include <cstddef>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/errors.hpp"

namespace edgeland::detail {

inline void require_query_point(Point64 p, std::size_t index, const char* name) {
  if (!in_range(p)) throw CoordinateOutOfRange::query_argument(index, name, p);
}

inline void require_query_box(const Box64& box) {
  require_query_point(box.min, 0, "box min");
  require_query_point(box.max, 1, "box max");
}

}  // namespace edgeland::detail
