// The pinned hashes (pinned_sequence.hpp) from a build of the whole library at one optimisation
// level (tests/CMakeLists.txt compiles this at -O0 and at -O3; scripts/wasm_determinism.sh into
// WebAssembly): the edits one by one and in frame batches. Exit 0 when all agree.
#include <cstdio>

#include "pinned_sequence.hpp"

namespace {

// Prints the hash of `l` and whether it is the pinned one.
bool agrees(const char* name, const edgeland::Landscape& l, std::uint64_t pinned) {
  const std::uint64_t h = l.state_hash();
  std::printf("%s %016llx%s\n", name, static_cast<unsigned long long>(h),
              h == pinned ? "" : " (pinned: DIFFERENT)");
  return h == pinned;
}

}  // namespace

int main() {
  using namespace edgeland::pinned;
  bool ok = agrees("quadtree", run({}), kQuadtreeHash);
  ok = agrees("kd-tree", run(kd_tree_config()), kKdTreeHash) && ok;
  ok = agrees("regions", run(regions_config()), kRegionsHash) && ok;
  ok = agrees("quadtree batches", run_batches({}), kQuadtreeBatchHash) && ok;
  ok = agrees("kd-tree batches", run_batches(kd_tree_config()), kKdTreeBatchHash) && ok;
  ok = agrees("regions batches", run_batches(regions_config()), kRegionsBatchHash) && ok;
  std::printf("%s\n", ok ? "pinned hashes agree" : "pinned hashes DIFFER");
  return ok ? 0 : 1;
}
