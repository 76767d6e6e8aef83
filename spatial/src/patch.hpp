#pragma once
// A PATCH applied to a state (Landscape::apply_delta): the subtrees read by the save file's
// hardened reader at their paths, the ancestors rebuilt and checked, ids checked over the whole
// world, areas and counters moved. Builds the next state apart; the current one is untouched.
#include "edgeland/spatial/delta.hpp"
#include "edit.hpp"

namespace edgeland::detail {

// Throws DeltaError (a rule broken: the offset is within the entry's subtree), DeltaMismatch
// (kNodeHash) or LimitExceeded.
EditResult apply_patch(const LandscapeState& state, const Delta& patch);

}  // namespace edgeland::detail
