// DivergenceSearch (delta.hpp; spatial/README.md "Divergence"): the Merkle tree compared level
// by level, descending only where the hashes differ.
#include <stdexcept>

#include "edgeland/spatial/delta.hpp"

namespace edgeland {

DivergenceSearch::DivergenceSearch(TreePath start) { questions_.push_back(std::move(start)); }

DivergenceSearch::DivergenceSearch(std::vector<TreePath> starts) : questions_(std::move(starts)) {}

// A node whose hashes differ: its differing children are the next questions when both sides
// are inner nodes of the same shape whose children are known; otherwise the node is patched
// whole.
void DivergenceSearch::answer(const Landscape& local,
                              const std::vector<std::optional<NodeDigest>>& remote) {
  if (remote.size() != questions_.size())
    throw std::invalid_argument("DivergenceSearch::answer: one digest per question");
  std::vector<TreePath> next;
  for (std::size_t q = 0; q < remote.size(); ++q) {
    const TreePath& path = questions_[q];
    const std::optional<NodeDigest> mine = local.node_digest(path);
    const std::optional<NodeDigest>& theirs = remote[q];
    if (!mine || !theirs) {
      if (mine || theirs) differing_.push_back(path);
      continue;
    }
    if (mine->hash == theirs->hash) continue;
    const bool descend = !mine->cell && !theirs->cell && mine->loaded && theirs->loaded &&
                         mine->children.size() == theirs->children.size();
    if (!descend) {
      differing_.push_back(path);
      continue;
    }
    for (std::size_t i = 0; i < mine->children.size(); ++i) {
      if (mine->children[i] == theirs->children[i]) continue;
      TreePath child = path;
      child.push_back(static_cast<std::uint8_t>(i));
      next.push_back(std::move(child));
    }
  }
  ++rounds_;
  questions_ = std::move(next);
}

}  // namespace edgeland
