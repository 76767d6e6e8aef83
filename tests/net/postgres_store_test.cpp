// The PostgreSQL store's rules (issue 37, item 6; store/README.md "How a region changes owner"),
// against the server tests/net/scenarios.py two-servers starts (EDGELAND_TEST_POSTGRES is its
// libpq conninfo, a database of its own; this executable is run only by that scenario): a server
// commits only the regions it owns; claims give each region to the first server that asks; a
// hand-over moves a region with its last record in one transaction, after which the old owner
// cannot write it; a row never goes back; every row comes back through the cursor.
#include "edgeland/store/postgres_store.hpp"

#include <gtest/gtest.h>
#include <libpq-fe.h>

#include <cstdlib>

#include "edgeland/spatial/delta.hpp"

namespace edgeland::store {
namespace {

std::string conninfo() {
  const char* c = std::getenv("EDGELAND_TEST_POSTGRES");
  if (!c) throw std::runtime_error("EDGELAND_TEST_POSTGRES is not set (run by scenarios.py)");
  return c;
}

// Each test starts from no tables (the store makes them as it opens).
class PostgresStore : public ::testing::Test {
 protected:
  void SetUp() override {
    PGconn* db = PQconnectdb(conninfo().c_str());
    ASSERT_EQ(PQstatus(db), CONNECTION_OK) << PQerrorMessage(db);
    PQclear(PQexec(db, "SET client_min_messages = warning"));
    PGresult* r = PQexec(db, "DROP TABLE IF EXISTS regions, world, owners");
    EXPECT_EQ(PQresultStatus(r), PGRES_COMMAND_OK) << PQerrorMessage(db);
    PQclear(r);
    PQfinish(db);
  }
};

Landscape world(int edits, int depth) {
  LandscapeConfig c;
  c.region_depth = depth;
  c.region_ids = true;
  Landscape w({{0, 0}, {2048, 2048}}, 1, c);
  for (std::int64_t i = 0; i < edits; ++i)
    w.carve(PolygonSet{{{100 + 40 * i, 100}, {130 + 40 * i, 100}, {115 + 40 * i, 140}}});
  return w;
}

TEST_F(PostgresStore, AServerCommitsOnlyWhatItOwnsAndAHandOverMovesARegion) {
  const Landscape w = world(30, 2);
  const std::vector<TreePath> paths = w.region_paths();
  PostgresRegionStore a(conninfo(), "test-a"), b(conninfo(), "test-b");
  const std::vector<TreePath> mine(paths.begin(), paths.begin() + 8);
  const std::vector<TreePath> a_owns = a.claim(mine);
  const std::vector<TreePath> b_owns = b.claim(paths);  // the rest: the first eight are taken
  EXPECT_EQ(a_owns.size(), 8u);
  EXPECT_EQ(b_owns.size(), paths.size() - 8);
  EXPECT_EQ(a.owner(paths[0]), "test-a");
  EXPECT_EQ(a.owner(paths[15]), "test-b");
  // A commit with one region A does not own is refused whole.
  EXPECT_THROW(
      a.commit({stored_region(w, paths[0], 1), stored_region(w, paths[15], 1)}, std::nullopt),
      StoreError);
  EXPECT_FALSE(a.region(paths[0]).has_value());
  a.commit({stored_region(w, paths[0], 1)}, std::nullopt);
  EXPECT_EQ(a.region(paths[0])->hash, w.node_digest(paths[0])->hash);
  // A hands region 0 to B with its last record; then A cannot write it, B can.
  a.hand_over(stored_region(w, paths[0], 2), "test-b");
  EXPECT_EQ(a.owner(paths[0]), "test-b");
  EXPECT_EQ(b.region(paths[0])->seq, 2u);
  EXPECT_THROW(a.commit({stored_region(w, paths[0], 3)}, std::nullopt), StoreError);
  b.commit({stored_region(w, paths[0], 3)}, std::nullopt);
  EXPECT_EQ(b.region(paths[0])->seq, 3u);
  // A row never goes back.
  b.commit({stored_region(w, paths[0], 1)}, std::nullopt);
  EXPECT_EQ(b.region(paths[0])->seq, 3u);
}

TEST_F(PostgresStore, AWholeWorldComesBackRowByRow) {
  const Landscape w = world(20, 3);
  PostgresRegionStore s(conninfo());
  write_world(s, w, 20);
  Landscape opened = open_world(s);
  EXPECT_EQ(opened.state_hash(), w.state_hash());
  for (const TreePath& p : opened.region_paths()) load_region(s, opened, p);
  EXPECT_TRUE(opened.check().ok());
  EXPECT_EQ(opened.state_hash(), w.state_hash());
}

}  // namespace
}  // namespace edgeland::store
