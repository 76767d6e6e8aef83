// Divergence found and repaired through node hashes (issue 37, item 2): a client whose world
// differs from the server's finds the differing nodes by comparing digests level by level, one
// round per level, and PATCHes only those; the repair costs a small part of a whole save. A
// hostile PATCH is refused with a typed error and the world as it was.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "edgeland/spatial/delta.hpp"
#include "pinned_sequence.hpp"
#include "save_file.hpp"

namespace edgeland {
namespace {

std::string save_of(const Landscape& l) {
  std::ostringstream out;
  l.save(out);
  return out.str();
}

Landscape load_of(const std::string& bytes, const LandscapeLimits& limits = {}) {
  std::istringstream in(bytes);
  return Landscape::load(in, limits);
}

// The pinned sequence's world: 400 edits of every kind, about a thousand cells.
Landscape server_world() { return pinned::run({}); }

// What the exchange costs, in the encoding net/ uses: a question is its path (a length byte and
// one byte a level), an answer the node's hash, a flags byte and the children's hashes.
struct RepairCost {
  std::size_t rounds = 0, questions = 0, exchange_bytes = 0, patch_bytes = 0, patched = 0;
};

RepairCost repair(Landscape& client, const Landscape& server, std::uint64_t sequence) {
  RepairCost cost;
  DivergenceSearch search;
  while (!search.done()) {
    std::vector<std::optional<NodeDigest>> answers;
    for (const TreePath& path : search.questions()) {
      answers.push_back(server.node_digest(path));
      cost.exchange_bytes += 1 + path.size() + 9 + 8 * answers.back()->children.size();
      ++cost.questions;
    }
    search.answer(client, answers);
  }
  cost.rounds = search.rounds();
  cost.patched = search.differing().size();
  const std::string bytes =
      encode_delta(patch_delta(server, sequence, search.differing(), client.state_hash()));
  cost.patch_bytes = bytes.size();
  client.apply_delta(decode_delta(bytes));
  return cost;
}

// A client's cell corrupted on purpose: the polygon in the middle of its save file takes a fresh
// id (the file still loads: a valid world, but not the server's).
Landscape corrupted_copy(const Landscape& server) {
  fuzz::SaveFile file = *fuzz::decode_save(save_of(server));
  const std::size_t polygon_index = server.stats().polygons / 2;
  std::size_t seen = 0;
  for (fuzz::SavedNode& node : file.nodes)
    for (fuzz::SavedPolygon& p : node.polygons)
      if (seen++ == polygon_index) p.id = file.next_id;
  ++file.next_id;
  return load_of(fuzz::encode_save(file));
}

TEST(DeltaRepair, ACorruptedCellIsFoundLevelByLevelAndPatchedAlone) {
  const Landscape server = server_world();
  Landscape client = corrupted_copy(server);
  ASSERT_NE(client.state_hash(), server.state_hash());
  ASSERT_TRUE(client.check().ok());
  const RepairCost cost = repair(client, server, 400);
  EXPECT_EQ(client.state_hash(), server.state_hash());
  EXPECT_TRUE(client.check().ok());
  const std::size_t save = save_of(server).size();
  // One round per level down to the corrupted cell, one node asked per level but the root's
  // children (the root is asked once; each later round asks the one child that differs).
  EXPECT_EQ(cost.patched, 1u);
  EXPECT_LE(cost.rounds, server.stats().depth + 1);
  EXPECT_EQ(cost.questions, cost.rounds);
  EXPECT_LT(cost.exchange_bytes + cost.patch_bytes, save / 20);
  std::printf(
      "repair of one corrupted cell: %zu rounds, %zu bytes of digests, %zu bytes of patch,"
      " against a save of %zu bytes (%.2f%%)\n",
      cost.rounds, cost.exchange_bytes, cost.patch_bytes, save,
      100.0 * static_cast<double>(cost.exchange_bytes + cost.patch_bytes) /
          static_cast<double>(save));
}

// A client that applied an edit the server never made: every cell the edit changed (several,
// split or merged) is patched, and its ids are the server's again.
TEST(DeltaRepair, AStrayLocalEditIsUndoneByPatchingTheCellsItChanged) {
  const Landscape server = server_world();
  Landscape client = server;
  client.carve(PolygonSet{pinned::blob({2000, 2000}, 300)});
  client.fill(PolygonSet{pinned::blob({600, 3000}, 80)}, 7);
  ASSERT_NE(client.state_hash(), server.state_hash());
  const RepairCost cost = repair(client, server, 400);
  EXPECT_EQ(client.state_hash(), server.state_hash());
  EXPECT_GE(cost.patched, 2u);
  EXPECT_LT(cost.patch_bytes, save_of(server).size() / 4);
}

// Every node agrees but the next id does not (a polygon made and carved away again): a PATCH
// with no entries carries the counter.
TEST(DeltaRepair, AnIdCounterAloneIsRepairedByAPatchWithoutEntries) {
  Landscape server({{0, 0}, {4096, 4096}});
  Landscape client = server;
  const PolygonSet blob{pinned::blob({500, 500}, 40)};
  client.fill(blob, 3);
  client.carve(blob);
  ASSERT_EQ(client.node_digest({})->hash, server.node_digest({})->hash);
  ASSERT_NE(client.state_hash(), server.state_hash());
  const RepairCost cost = repair(client, server, 0);
  EXPECT_EQ(cost.patched, 0u);
  EXPECT_EQ(client.state_hash(), server.state_hash());
}

TEST(DeltaRepair, NodeDigestsNameTheTreeAndItsChildren) {
  const Landscape l = server_world();
  const NodeDigest root = *l.node_digest({});
  EXPECT_EQ(root.box, l.world());
  EXPECT_FALSE(root.cell);
  EXPECT_EQ(root.children.size(), 4u);
  for (std::uint8_t i = 0; i < 4; ++i) EXPECT_EQ(l.node_digest({i})->hash, root.children[i]);
  EXPECT_FALSE(l.node_digest({4}).has_value());
  TreePath deep{0};
  while (!l.node_digest(deep)->cell) deep.push_back(0);
  deep.push_back(0);
  EXPECT_FALSE(l.node_digest(deep).has_value());
  EXPECT_THROW(l.patch_entry(deep), InvalidPath);
  EXPECT_THROW((void)l.drawn_digest(deep), InvalidPath);
}

// --- hostile patches ------------------------------------------------------------------------
class HostilePatch : public ::testing::Test {
 protected:
  void SetUp() override {
    client = server;
    client.carve(PolygonSet{pinned::blob({1000, 1000}, 200)});
    hash = client.state_hash();
    TreePath leaf{};
    while (!server.node_digest(leaf)->cell) leaf.push_back(1);
    cell = leaf;
  }
  void expect_refused(const Delta& d) {
    EXPECT_THROW(
        client.apply_delta(decode_delta(encode_delta(d)), {.base = false, .result = false}),
        LandscapeError);
    EXPECT_EQ(client.state_hash(), hash);
    EXPECT_TRUE(client.check().ok());
  }
  Landscape server = server_world();
  Landscape client = server;
  std::uint64_t hash = 0;
  TreePath cell;
};

TEST_F(HostilePatch, AWrongNodeHashIsAMismatch) {
  Delta d = patch_delta(server, 1, {cell});
  d.patches[0].hash ^= 1;
  try {
    client.apply_delta(d, {.base = false, .result = false});
    FAIL();
  } catch (const DeltaMismatch& e) {
    EXPECT_EQ(e.field, DeltaMismatch::Field::kNodeHash);
  }
  EXPECT_EQ(client.state_hash(), hash);
}

TEST_F(HostilePatch, APathThroughACellOrNestingAnotherIsRefused) {
  Delta d = patch_delta(server, 1, {cell});
  d.patches[0].path.push_back(0);
  expect_refused(d);
  d = patch_delta(server, 1, {{}, {0}});
  expect_refused(d);
}

TEST_F(HostilePatch, GarbageOrATruncatedSubtreeIsRefused) {
  for (const std::string& subtree :
       {std::string("\x05", 1), std::string("\x00", 1),
        std::string("\x00\x01\x01\x01\x03\x00\x00", 7), std::string("\x01\x00\x00", 3)}) {
    Delta d = patch_delta(server, 1, {cell});
    d.patches[0].subtree = subtree;
    expect_refused(d);
  }
  Delta d = patch_delta(server, 1, {cell});
  d.patches[0].subtree += '\0';
  expect_refused(d);
}

// A partial repair that would bring in ids the client's own stray edit used elsewhere: the ids
// would be there twice, or at or above the patch's next id.
TEST_F(HostilePatch, IdsUsedElsewhereAreRefused) {
  Landscape ahead = server;
  ahead.fill(PolygonSet{pinned::blob({3500, 300}, 150)}, 9);
  DivergenceSearch search;
  while (!search.done()) {
    std::vector<std::optional<NodeDigest>> answers;
    for (const TreePath& p : search.questions()) answers.push_back(ahead.node_digest(p));
    search.answer(client, answers);
  }
  ASSERT_GE(search.differing().size(), 2u);
  std::vector<TreePath> far_only;
  for (const TreePath& p : search.differing())
    if (!ahead.node_digest(p)->box.overlaps(Box64{{800, 800}, {1200, 1200}})) far_only.push_back(p);
  ASSERT_FALSE(far_only.empty());
  expect_refused(patch_delta(ahead, 1, far_only));
  // The whole repair is fine.
  client.apply_delta(patch_delta(ahead, 1, search.differing()), {.base = false});
  EXPECT_EQ(client.state_hash(), ahead.state_hash());
}

TEST_F(HostilePatch, AWorldPastItsLimitsIsRefused) {
  LandscapeLimits small;
  small.max_cells = server.stats().cells - 1;
  Landscape limited = load_of(save_of(Landscape({{0, 0}, {4096, 4096}}, 1)), small);
  Delta d = patch_delta(server, 1, {{}});
  d.header.world = limited.world_hash();
  const std::uint64_t before = limited.state_hash();
  EXPECT_THROW(limited.apply_delta(d, {.base = false}), LimitExceeded);
  EXPECT_EQ(limited.state_hash(), before);
}

}  // namespace
}  // namespace edgeland
