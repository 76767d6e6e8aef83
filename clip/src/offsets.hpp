#pragma once
// Compressed rows (CSR): the items of row r are items[begin[r] .. begin[r + 1]). The plane
// graph, snap rounding and the routes all group items by an integer id this way: count each
// row's items into begin[r + 1], then add_up_counts turns the counts into offsets.
#include <cstddef>

namespace edgeland::detail {

// begin[0] == 0 and begin[r + 1] holds row r's count on entry; row r's first offset after.
template <class Vector>
void add_up_counts(Vector& begin) {
  for (std::size_t r = 1; r < begin.size(); ++r) begin[r] += begin[r - 1];
}

}  // namespace edgeland::detail
