// The pinned hashes (pinned_sequence.hpp) from a build of the whole library at one optimisation
// level (tests/CMakeLists.txt compiles this at -O0 and at -O3). Exit 0 when both agree.
#include <cstdio>

#include "pinned_sequence.hpp"

int main() {
  const std::uint64_t quad = edgeland::pinned::run({}).state_hash();
  const std::uint64_t kd = edgeland::pinned::run(edgeland::pinned::kd_tree_config()).state_hash();
  const std::uint64_t regions =
      edgeland::pinned::run(edgeland::pinned::regions_config()).state_hash();
  std::printf("quadtree %016llx kd-tree %016llx regions %016llx\n",
              static_cast<unsigned long long>(quad), static_cast<unsigned long long>(kd),
              static_cast<unsigned long long>(regions));
  const bool ok = quad == edgeland::pinned::kQuadtreeHash && kd == edgeland::pinned::kKdTreeHash &&
                  regions == edgeland::pinned::kRegionsHash;
  std::printf("%s\n", ok ? "pinned hashes agree" : "pinned hashes DIFFER");
  return ok ? 0 : 1;
}
