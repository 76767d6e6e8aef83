// Region stores and streaming (issue 37, item 4; store/README.md): a world written to SQLite and
// opened again as stubs loads to the same world; a row never goes back to an older record; a
// damaged row is a typed error; a world streamed through the store under a budget of a sixteenth
// of its in-memory size has the in-memory run's state hash after every edit, and goes on after
// it was closed and opened again.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "edgeland/spatial/delta.hpp"
#include "edgeland/store/sqlite_store.hpp"
#include "edgeland/store/streaming_world.hpp"
#include "edgeland/store/sweep_edits.hpp"

namespace edgeland::store {
namespace {

// A database file of its own for each test, removed after it.
class StoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("edgeland_store_" + std::to_string(getpid()) + "_" + info->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string db() const { return (dir_ / "regions.db").string(); }
  std::filesystem::path dir_;
};

// A small sweep: 4096^2, 64 regions, about 40 vertices a fill.
const SweepEdits& sweep() {
  static const SweepEdits s(4096, 3);
  return s;
}

Landscape swept(std::size_t edits) {
  Landscape w(sweep().world(), kEmpty, sweep().config());
  for (std::size_t i = 0; i < edits; ++i) apply_edit(w, sweep().at(i));
  return w;
}

TEST_F(StoreTest, AWorldWrittenAndOpenedAgainLoadsToTheSameWorld) {
  const Landscape w = swept(700);
  {
    SqliteRegionStore s(db());
    write_world(s, w, 700);
  }
  SqliteRegionStore s(db());
  EXPECT_EQ(s.integrity_check(), "ok");
  EXPECT_EQ(s.world()->seq, 700u);
  Landscape opened = open_world(s);
  EXPECT_EQ(opened.state_hash(), w.state_hash());
  for (const TreePath& p : opened.region_paths()) {
    EXPECT_FALSE(opened.region_loaded(p));
    load_region(s, opened, p);
  }
  EXPECT_TRUE(opened.check().ok());
  EXPECT_EQ(opened.state_hash(), w.state_hash());
  std::size_t rows = 0;
  s.for_each_region([&](const StoredRegion& r) {
    EXPECT_EQ(r.hash, w.node_digest(r.path)->hash);
    ++rows;
  });
  EXPECT_EQ(rows, 64u);
}

TEST_F(StoreTest, ARowIsNeverReplacedByAnOlderRecord) {
  const Landscape early = swept(100), late = swept(300);
  SqliteRegionStore s(db());
  // The sweep fills the region of (1100, 600) with edits 160 to 175.
  const TreePath path = late.regions_meeting({{1100, 600}, {1101, 601}}).front();
  s.commit({stored_region(late, path, 300)}, std::nullopt);
  s.commit({stored_region(early, path, 100)}, std::nullopt);
  EXPECT_EQ(s.region(path)->seq, 300u);
  EXPECT_EQ(s.region(path)->hash, late.node_digest(path)->hash);
  EXPECT_NE(early.node_digest(path)->hash, late.node_digest(path)->hash);
}

TEST_F(StoreTest, ADamagedRowIsATypedErrorAndTheWorldStaysAsItWas) {
  const Landscape w = swept(200);
  SqliteRegionStore s(db());
  write_world(s, w, 200);
  Landscape opened = open_world(s);
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(db().c_str(), &raw), SQLITE_OK);
  // One byte in the middle of region {0 0 0}'s record changed.
  ASSERT_EQ(sqlite3_exec(raw,
                         "UPDATE regions SET bytes = substr(bytes, 1, 40) || x'ff' || "
                         "substr(bytes, 42) WHERE path = x'000000'",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(raw);
  // The record's checksum fails when it is loaded, and when the world is opened again.
  const std::uint64_t hash = opened.state_hash();
  EXPECT_THROW(open_world(s), LoadError);
  EXPECT_THROW(load_region(s, opened, {0, 0, 0}), LoadError);
  EXPECT_FALSE(opened.region_loaded({0, 0, 0}));
  EXPECT_EQ(opened.state_hash(), hash);
}

// Issue 37, item 4, the short form of scripts/streaming_run.sh: every edit of the sweep applied
// in memory and through the store under a sixteenth of the in-memory world's bytes; the hashes
// agree after every edit, and the loaded regions stay within the budget.
TEST_F(StoreTest, AWorldStreamedUnderABudgetHasTheInMemoryHashAfterEveryEdit) {
  const Landscape whole = swept(sweep().size());
  const std::size_t budget = whole.stats().bytes / 16;
  {
    SqliteRegionStore s(db());
    write_world(s, Landscape(sweep().world(), kEmpty, sweep().config()), 0);
  }
  SqliteRegionStore s(db());
  StreamingWorld streamed(s, budget);
  Landscape memory(sweep().world(), kEmpty, sweep().config());
  for (std::size_t i = 0; i < sweep().size(); ++i) {
    apply_edit(memory, sweep().at(i));
    streamed.apply(sweep().at(i));
    ASSERT_EQ(streamed.world().state_hash(), memory.state_hash()) << i;
  }
  streamed.flush();
  const StreamingWorld::Stats& st = streamed.stats();
  EXPECT_LE(st.peak_loaded_bytes, budget);
  EXPECT_GT(st.loads, 64u);  // the tunnels bring every region back from the store
  EXPECT_GT(st.evictions, 64u);
  Landscape reopened = open_world(s);
  for (const TreePath& p : reopened.region_paths()) load_region(s, reopened, p);
  EXPECT_EQ(reopened.state_hash(), whole.state_hash());
  EXPECT_TRUE(reopened.check().ok());
}

TEST_F(StoreTest, AStreamedWorldClosedAndOpenedAgainGoesOn) {
  const std::size_t half = sweep().size() / 2;
  {
    SqliteRegionStore s(db());
    write_world(s, Landscape(sweep().world(), kEmpty, sweep().config()), 0);
    StreamingWorld w(s, 1 << 20);
    while (w.sequence() < half) w.apply(sweep().at(w.sequence()));
    w.flush();
  }
  SqliteRegionStore s(db());
  StreamingWorld w(s, 1 << 20);
  // It goes on from the first edit some region has not seen (the regions the first half never
  // reached are still at 0), and passes each edit over the regions that have seen it.
  EXPECT_LE(w.sequence(), half);
  while (w.sequence() < sweep().size()) w.apply(sweep().at(w.sequence()));
  EXPECT_EQ(w.world().state_hash(), swept(sweep().size()).state_hash());
}

}  // namespace
}  // namespace edgeland::store
