#include "tree_paths.hpp"

#include <algorithm>

#include "edgeland/spatial/delta.hpp"

namespace edgeland::detail {

std::vector<NodePtr> nodes_on(const NodePtr& root, const TreePath& path) {
  std::vector<NodePtr> chain{root};
  for (const std::uint8_t i : path) {
    const Node& n = *chain.back();
    if (i >= n.child_count) return {};
    chain.push_back(n.children[i]);
  }
  return chain;
}

NodePtr replace_node(const std::vector<NodePtr>& chain, const TreePath& path, NodePtr node) {
  for (std::size_t level = path.size(); level-- > 0;) {
    const Node& parent = *chain[level];
    std::vector<NodePtr> children(parent.children.begin(),
                                  parent.children.begin() + parent.child_count);
    children[path[level]] = std::move(node);
    node = make_inner(parent.box, parent.depth, children, parent.region_next);
  }
  return node;
}

}  // namespace edgeland::detail

namespace edgeland {

// A loop rather than vector's <=>, whose memcmp g++ 12 -O3 warns about (-Wstringop-overread, a
// false positive).
bool path_less(const TreePath& a, const TreePath& b) noexcept {
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] != b[i]) return a[i] < b[i];
  return a.size() < b.size();
}

bool path_within(const TreePath& a, const TreePath& b) noexcept {
  return a.size() >= b.size() && std::equal(b.begin(), b.end(), a.begin());
}

}  // namespace edgeland
