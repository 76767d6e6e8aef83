// The pinned state hashes (pinned_sequence.hpp) in the test build (gcc -O2 with checked
// arithmetic in scripts/test.sh, clang with sanitizers in .ci/run). The same sequence is also
// built at -O0 and -O3 (tests/CMakeLists.txt, spatial.determinism_*).
#include <gtest/gtest.h>

#include "edgeland/spatial/delta.hpp"
#include "pinned_sequence.hpp"

namespace edgeland::test {
namespace {

TEST(LandscapeDeterminism, PinnedSequenceGivesThePinnedHash) {
  EXPECT_EQ(pinned::run({}).state_hash(), pinned::kQuadtreeHash);
  EXPECT_EQ(pinned::run(pinned::kd_tree_config()).state_hash(), pinned::kKdTreeHash);
  EXPECT_EQ(pinned::run(pinned::regions_config()).state_hash(), pinned::kRegionsHash);
}

TEST(LandscapeDeterminism, PinnedBatchesGiveThePinnedHash) {
  EXPECT_EQ(pinned::run_batches({}).state_hash(), pinned::kQuadtreeBatchHash);
  EXPECT_EQ(pinned::run_batches(pinned::kd_tree_config()).state_hash(), pinned::kKdTreeBatchHash);
  EXPECT_EQ(pinned::run_batches(pinned::regions_config()).state_hash(), pinned::kRegionsBatchHash);
}

TEST(LandscapeDeterminism, PinsBelongToTheAlgorithmVersion) {
  EXPECT_EQ(kAlgorithmVersion, pinned::kPinnedAlgorithmVersion);
}

TEST(LandscapeDeterminism, CheckedModeChangesNothingButTheChecks) {
  Landscape plain = pinned::run({});
  Landscape checked({{0, 0}, {4096, 4096}}, 1);
  checked.set_checked(true);
  // The same first edits with checking on give the same states.
  Landscape unchecked({{0, 0}, {4096, 4096}}, 1);
  for (int i = 0; i < 30; ++i) {
    const PolygonSet shape{pinned::blob({137 * i % 4096, 211 * i % 4096}, 60 + i)};
    checked.carve(shape);
    unchecked.carve(shape);
    ASSERT_EQ(checked.state_hash(), unchecked.state_hash()) << i;
  }
  EXPECT_TRUE(plain.check().ok());
}

}  // namespace
}  // namespace edgeland::test
