// SqliteRegionStore (sqlite_store.hpp): the tables of store/README.md in one SQLite file.
#include "edgeland/store/sqlite_store.hpp"

#include <sqlite3.h>

namespace edgeland::store {
namespace {

// One prepared statement, finalised whatever happens.
class Statement {
 public:
  Statement(sqlite3* db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) fail("prepare");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  void bind(int i, std::int64_t v) { check(sqlite3_bind_int64(stmt_, i, v), "bind"); }
  void bind_blob(int i, const void* data, std::size_t n) {
    // A zero-length blob still binds as a blob (not NULL): SQLite wants a non-null pointer.
    static const char kNothing = 0;
    check(sqlite3_bind_blob64(stmt_, i, n ? data : &kNothing, n, SQLITE_TRANSIENT), "bind");
  }
  // True while rows come; false when done.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail("step");
    return false;
  }
  void reset() { sqlite3_reset(stmt_); }
  std::int64_t integer(int column) { return sqlite3_column_int64(stmt_, column); }
  std::string blob(int column) {
    const auto* data = static_cast<const char*>(sqlite3_column_blob(stmt_, column));
    const auto n = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
    return data ? std::string(data, n) : std::string();
  }
  std::string text(int column) {
    const unsigned char* t = sqlite3_column_text(stmt_, column);
    return t ? std::string(reinterpret_cast<const char*>(t)) : std::string();
  }

 private:
  void check(int rc, const char* what) {
    if (rc != SQLITE_OK) fail(what);
  }
  [[noreturn]] void fail(const char* what) {
    throw StoreError(std::string("sqlite ") + what + ": " + sqlite3_errmsg(db_));
  }
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

TreePath path_of(const std::string& blob) { return TreePath(blob.begin(), blob.end()); }

StoredRegion region_row(Statement& s) {
  return StoredRegion{path_of(s.blob(0)), s.blob(1), static_cast<std::uint64_t>(s.integer(2)),
                      static_cast<std::uint64_t>(s.integer(3))};
}

constexpr const char* kSchema = R"(
CREATE TABLE IF NOT EXISTS regions (path BLOB PRIMARY KEY, bytes BLOB NOT NULL,
                                    hash INTEGER NOT NULL, seq INTEGER NOT NULL);
CREATE TABLE IF NOT EXISTS world (id INTEGER PRIMARY KEY CHECK (id = 1),
  min_x INTEGER NOT NULL, min_y INTEGER NOT NULL, max_x INTEGER NOT NULL, max_y INTEGER NOT NULL,
  tree INTEGER NOT NULL, edge_cap INTEGER NOT NULL, merge_below INTEGER NOT NULL,
  min_cell_size INTEGER NOT NULL, grid_depth INTEGER NOT NULL, region_depth INTEGER NOT NULL,
  region_ids INTEGER NOT NULL, next_id INTEGER NOT NULL, seq INTEGER NOT NULL);
)";

// A row is replaced only by a record of a later or equal sequence number.
constexpr const char* kPutRegion =
    "INSERT INTO regions (path, bytes, hash, seq) VALUES (?1, ?2, ?3, ?4) "
    "ON CONFLICT (path) DO UPDATE SET bytes = excluded.bytes, hash = excluded.hash, "
    "seq = excluded.seq WHERE excluded.seq >= regions.seq";

constexpr const char* kPutWorld =
    "INSERT OR REPLACE INTO world VALUES (1, ?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, "
    "?13)";

void bind_world(Statement& s, const WorldRecord& w) {
  const std::array<std::int64_t, 13> values = world_columns(w);
  for (std::size_t i = 0; i < values.size(); ++i) s.bind(static_cast<int>(i + 1), values[i]);
}

WorldRecord world_row(Statement& s) {
  std::array<std::int64_t, 13> values{};
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = s.integer(static_cast<int>(i));
  return world_of_columns(values);
}

}  // namespace

SqliteRegionStore::SqliteRegionStore(const std::string& path) {
  if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw StoreError("sqlite open " + path + ": " + message);
  }
  // A writer waits for another's transaction instead of failing at once.
  sqlite3_busy_timeout(db_, 10000);
  try {
    exec("PRAGMA journal_mode = WAL; PRAGMA synchronous = FULL;");
    exec(kSchema);
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

SqliteRegionStore::~SqliteRegionStore() { sqlite3_close(db_); }

void SqliteRegionStore::exec(const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : sqlite3_errmsg(db_);
    sqlite3_free(error);
    throw StoreError(std::string("sqlite: ") + message);
  }
}

std::optional<WorldRecord> SqliteRegionStore::world() {
  Statement s(db_,
              "SELECT min_x, min_y, max_x, max_y, tree, edge_cap, merge_below, min_cell_size, "
              "grid_depth, region_depth, region_ids, next_id, seq FROM world WHERE id = 1");
  if (!s.step()) return std::nullopt;
  return world_row(s);
}

std::optional<StoredRegion> SqliteRegionStore::region(const TreePath& path) {
  Statement s(db_, "SELECT path, bytes, hash, seq FROM regions WHERE path = ?1");
  s.bind_blob(1, path.data(), path.size());
  if (!s.step()) return std::nullopt;
  return region_row(s);
}

void SqliteRegionStore::for_each_region(const std::function<void(const StoredRegion&)>& visit) {
  Statement s(db_, "SELECT path, bytes, hash, seq FROM regions ORDER BY path");
  while (s.step()) visit(region_row(s));
}

void SqliteRegionStore::commit(const std::vector<StoredRegion>& regions,
                               const std::optional<WorldRecord>& world) {
  exec("BEGIN IMMEDIATE");
  try {
    Statement row(db_, kPutRegion);
    for (const StoredRegion& r : regions) {
      row.bind_blob(1, r.path.data(), r.path.size());
      row.bind_blob(2, r.record.data(), r.record.size());
      row.bind(3, static_cast<std::int64_t>(r.hash));
      row.bind(4, static_cast<std::int64_t>(r.seq));
      row.step();
      row.reset();
    }
    if (world) {
      Statement w(db_, kPutWorld);
      bind_world(w, *world);
      w.step();
    }
    exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

std::string SqliteRegionStore::integrity_check() {
  Statement s(db_, "PRAGMA integrity_check");
  return s.step() ? s.text(0) : std::string();
}

}  // namespace edgeland::store
