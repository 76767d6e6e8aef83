#pragma once
// Candidate pairs for exact tests: every pair of boxes that overlap (closed boxes), found by
// sorting on min x and sweeping (the scanbeam of thesis 3.3.2). O(n log n + pairs tested).
#include <cstdint>
#include <functional>
#include <vector>

#include "edgeland/kernel/bbox.hpp"

namespace edgeland::detail {

// Calls visit(i, j) once for every i < j whose boxes overlap.
void for_each_overlapping_pair(const std::vector<Box64>& boxes,
                               const std::function<void(std::uint32_t, std::uint32_t)>& visit);

// Calls visit(i, j) for every box i of `a` overlapping box j of `b`.
void for_each_overlapping_pair(const std::vector<Box64>& a, const std::vector<Box64>& b,
                               const std::function<void(std::uint32_t, std::uint32_t)>& visit);

}  // namespace edgeland::detail
