#pragma once
// Labeling (thesis 3.4): the state on the left of every half-edge, from the local rule at
// vertices, carried along edges, one point location per connected component.
#include <array>
#include <cstdint>
#include <vector>

#include "plane_graph.hpp"

namespace edgeland::detail {

enum class LabelMode : std::uint8_t {
  kOwner,          // per channel: index of the polygon covering the side, or -1
  kWinding,        // channel 0: winding number of all rings
  kOwnerAndCount,  // channel 0 as kOwner; channel 1: how many of its rings wind around the side
};

struct SideState {
  // Per channel (input_edges.hpp): the covering polygon of that operand (-1: none) in owner
  // modes, the winding number (channel 0) in kWinding, the count of rings (channel 1) in
  // kOwnerAndCount.
  std::array<std::int32_t, 2> by_channel{-1, -1};
  friend bool operator==(const SideState&, const SideState&) = default;
};

// The state outside everything.
SideState empty_state(LabelMode mode);

// left[h], the state on the left of half-edge h, for every h (reusing left's capacity).
// O(m log m).
//
// With check_single_cover (kOwner mode), it also checks that no face is covered twice by one
// channel: every crossing it makes must take the channel from no polygon into one (an edge of
// that polygon only), out of the current one, or from the current one straight into a
// neighbour across an edge they share in opposite directions. It stops and returns false at
// the first crossing that does not. Why that is a complete check: every side's state is the
// outer face's (true: nothing covers it), a copy of another side of the same face, or one
// crossing away from a state computed before; a crossing of that kind from a true state with
// coverage 0 or 1 yields the true state again. So if some face were covered twice or more (or
// negatively), the first such side labeled came from a checked crossing that failed. Only
// meaningful on an exact arrangement (nothing moved by snap rounding): the caller's business.
// Returns true otherwise.
bool label_sides(const PlaneGraph& g, LabelMode mode, std::vector<SideState>& left,
                 bool check_single_cover = false);

}  // namespace edgeland::detail
