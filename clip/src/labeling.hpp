#pragma once
// Labeling (thesis 3.4): the state on the left of every half-edge, from the local rule at
// vertices, carried along edges, one point location per connected component.
#include <array>
#include <cstdint>
#include <vector>

#include "planar_graph.hpp"

namespace edgeland::detail {

enum class LabelMode : std::uint8_t {
  kOwner,    // per channel: index of the polygon covering the side, or -1
  kWinding,  // channel 0: winding number of all rings
};

struct SideState {
  std::array<std::int32_t, 2> s{-1, -1};
  friend bool operator==(const SideState&, const SideState&) = default;
};

// The state outside everything.
SideState empty_state(LabelMode mode);

// left[h], the state on the left of half-edge h, for every h (reusing left's capacity).
// O(m log m).
void label_sides(const PlaneGraph& g, LabelMode mode, std::vector<SideState>& left);

}  // namespace edgeland::detail
