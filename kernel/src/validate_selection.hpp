#pragma once
// The rings a validation sweep looks at: polygons[members[r]] for r < members.size(), or all of
// polygons when members is empty (shared by the run sweep and the vertex sweep).
#include <cstddef>
#include <span>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

inline std::size_t selected_count(std::span<const Polygon> polygons,
                                  std::span<const std::size_t> members) noexcept {
  return members.empty() ? polygons.size() : members.size();
}

inline const Polygon& selected_ring(std::span<const Polygon> polygons,
                                    std::span<const std::size_t> members, std::size_t r) noexcept {
  return polygons[members.empty() ? r : members[r]];
}

}  // namespace edgeland::detail
