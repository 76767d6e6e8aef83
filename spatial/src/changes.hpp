#pragma once
// The change set of an edit, from the old and the new tree: the cells that differ, and which
// polygons (by id) left and arrived.
#include <vector>

#include "edgeland/kernel/scratch.hpp"
#include "node.hpp"

namespace edgeland::detail {

// Scratch arrays: an edit's diff allocates nothing in the steady state.
struct Changes {
  ScratchVector<NodePtr> old_cells;  // cells of the old tree that are gone
  ScratchVector<NodePtr> new_cells;  // cells of the new tree that are new
  // Inner nodes of the new tree that are new (their structure is what checked mode verifies).
  ScratchVector<NodePtr> new_inner;
};

// Walks both trees where they differ. O(size of the differing parts).
Changes diff(const NodePtr& old_root, const NodePtr& new_root);

// Removed and added polygons (by id), the new cells, the exact area change per material.
ChangeSet change_set(const Changes& changes);

}  // namespace edgeland::detail
