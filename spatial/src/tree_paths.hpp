#pragma once
// Nodes by path (types.hpp TreePath): finding the node a path names, and a root with the node at
// a path replaced (the persistent tree's path copy, as an edit makes it).
#include <vector>

#include "node.hpp"

namespace edgeland::detail {

// The nodes from the root down to the one `path` names (path.size() + 1 of them), or an empty
// vector when the path names no node (an index past a node's children, a step below a cell).
std::vector<NodePtr> nodes_on(const NodePtr& root, const TreePath& path);

// The root of the tree with the last node of `chain` (nodes_on) replaced by `node`, every
// ancestor rebuilt by make_inner (keeping its id counter).
NodePtr replace_node(const std::vector<NodePtr>& chain, const TreePath& path, NodePtr node);

}  // namespace edgeland::detail
