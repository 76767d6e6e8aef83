#pragma once
// One update's steps (the edits, then the detaches) as one GameUpdate: a later step's lists are
// taken into the earlier's; what one step added and a later one removed appears in neither.
#include "edgeland/game/game_types.hpp"

namespace edgeland::game_detail {

void take_changes(ChangeSet& into, ChangeSet&& more);
void take_chains(ChainUpdate& into, ChainUpdate&& more);

// The merged lists in order: removed ascending; the cells those that are still cells of
// `world`, once each, ascending by their corners; the area deltas by material.
void finish_changes(ChangeSet& changes, const Landscape& world);
void finish_chains(ChainUpdate& chains);

}  // namespace edgeland::game_detail
