// PostgresRegionStore (postgres_store.hpp): the tables of store/README.md through libpq, with
// bytea parameters and results in binary.
#include "edgeland/store/postgres_store.hpp"

#include <libpq-fe.h>

#include <memory>

namespace edgeland::store {
namespace {

// A result, cleared whatever happens.
using Result = std::unique_ptr<PGresult, decltype(&PQclear)>;

// The parameters of one statement: text for integers, binary for bytea.
struct Params {
  std::vector<std::string> values;
  std::vector<int> formats;
  void text(std::int64_t v) {
    values.push_back(std::to_string(v));
    formats.push_back(0);
  }
  void text(const std::string& v) {
    values.push_back(v);
    formats.push_back(0);
  }
  void binary(std::string v) {
    values.push_back(std::move(v));
    formats.push_back(1);
  }
};

std::string bytes_of(const TreePath& p) { return std::string(p.begin(), p.end()); }
TreePath path_of(const std::string& b) { return TreePath(b.begin(), b.end()); }

// A big-endian int8 of a binary result.
std::int64_t int8_at(const PGresult* r, int row, int column) {
  const auto* b = reinterpret_cast<const unsigned char*>(PQgetvalue(r, row, column));
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = v << 8 | b[i];
  return static_cast<std::int64_t>(v);
}

std::string bytea_at(const PGresult* r, int row, int column) {
  return std::string(PQgetvalue(r, row, column),
                     static_cast<std::size_t>(PQgetlength(r, row, column)));
}

Result run(pg_conn* db, const char* sql, const Params& p) {
  std::vector<const char*> values;
  std::vector<int> lengths;
  for (const std::string& v : p.values) {
    values.push_back(v.data());
    lengths.push_back(static_cast<int>(v.size()));
  }
  Result r(PQexecParams(db, sql, static_cast<int>(values.size()), nullptr, values.data(),
                        lengths.data(), p.formats.data(), 1),
           &PQclear);
  const ExecStatusType status = PQresultStatus(r.get());
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)
    throw StoreError(std::string("postgres: ") + PQerrorMessage(db));
  return r;
}

StoredRegion region_row(const PGresult* r, int row) {
  return StoredRegion{path_of(bytea_at(r, row, 0)), bytea_at(r, row, 1),
                      static_cast<std::uint64_t>(int8_at(r, row, 2)),
                      static_cast<std::uint64_t>(int8_at(r, row, 3))};
}

constexpr const char* kSchema = R"(
CREATE TABLE IF NOT EXISTS regions (path BYTEA PRIMARY KEY, bytes BYTEA NOT NULL,
                                    hash BIGINT NOT NULL, seq BIGINT NOT NULL);
CREATE TABLE IF NOT EXISTS world (id INTEGER PRIMARY KEY CHECK (id = 1),
  min_x BIGINT NOT NULL, min_y BIGINT NOT NULL, max_x BIGINT NOT NULL, max_y BIGINT NOT NULL,
  tree BIGINT NOT NULL, edge_cap BIGINT NOT NULL, merge_below BIGINT NOT NULL,
  min_cell_size BIGINT NOT NULL, grid_depth BIGINT NOT NULL, region_depth BIGINT NOT NULL,
  region_ids BIGINT NOT NULL, next_id BIGINT NOT NULL, seq BIGINT NOT NULL);
CREATE TABLE IF NOT EXISTS owners (path BYTEA PRIMARY KEY, server TEXT NOT NULL,
                                   epoch BIGINT NOT NULL);
)";

constexpr const char* kPutRegion =
    "INSERT INTO regions (path, bytes, hash, seq) VALUES ($1, $2, $3, $4) "
    "ON CONFLICT (path) DO UPDATE SET bytes = excluded.bytes, hash = excluded.hash, "
    "seq = excluded.seq WHERE regions.seq <= excluded.seq";

constexpr const char* kPutWorld =
    "INSERT INTO world VALUES (1, $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13) "
    "ON CONFLICT (id) DO UPDATE SET next_id = GREATEST(world.next_id, excluded.next_id), "
    "seq = GREATEST(world.seq, excluded.seq)";

Params world_params(const WorldRecord& w) {
  Params p;
  for (const std::int64_t v : world_columns(w)) p.text(v);
  return p;
}

WorldRecord world_row(const PGresult* r) {
  std::array<std::int64_t, 13> values{};
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = int8_at(r, 0, static_cast<int>(i));
  return world_of_columns(values);
}

Params region_params(const StoredRegion& row) {
  Params p;
  p.binary(bytes_of(row.path));
  p.binary(row.record);
  p.text(static_cast<std::int64_t>(row.hash));
  p.text(static_cast<std::int64_t>(row.seq));
  return p;
}

}  // namespace

PostgresRegionStore::PostgresRegionStore(const std::string& conninfo, std::string server)
    : db_(PQconnectdb(conninfo.c_str())), server_(std::move(server)) {
  if (PQstatus(db_) != CONNECTION_OK) {
    const std::string message = PQerrorMessage(db_);
    PQfinish(db_);
    throw StoreError("postgres connect: " + message);
  }
  try {
    exec("SET client_min_messages = warning");
    exec(kSchema);
  } catch (...) {
    PQfinish(db_);
    throw;
  }
}

PostgresRegionStore::~PostgresRegionStore() { PQfinish(db_); }

void PostgresRegionStore::exec(const char* sql) {
  Result r(PQexec(db_, sql), &PQclear);
  const ExecStatusType status = PQresultStatus(r.get());
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)
    throw StoreError(std::string("postgres: ") + PQerrorMessage(db_));
}

std::optional<WorldRecord> PostgresRegionStore::world() {
  const Result r = run(db_,
                       "SELECT min_x, min_y, max_x, max_y, tree, edge_cap, merge_below, "
                       "min_cell_size, grid_depth, region_depth, region_ids, next_id, seq "
                       "FROM world WHERE id = 1",
                       {});
  if (PQntuples(r.get()) == 0) return std::nullopt;
  return world_row(r.get());
}

std::optional<StoredRegion> PostgresRegionStore::region(const TreePath& path) {
  Params p;
  p.binary(bytes_of(path));
  const Result r = run(db_, "SELECT path, bytes, hash, seq FROM regions WHERE path = $1", p);
  if (PQntuples(r.get()) == 0) return std::nullopt;
  return region_row(r.get(), 0);
}

// Row by row through a cursor, so memory holds one batch of records at a time.
void PostgresRegionStore::for_each_region(const std::function<void(const StoredRegion&)>& visit) {
  exec("BEGIN");
  try {
    exec(
        "DECLARE every_region NO SCROLL CURSOR FOR "
        "SELECT path, bytes, hash, seq FROM regions ORDER BY path");
    for (;;) {
      const Result r = run(db_, "FETCH 64 FROM every_region", {});
      if (PQntuples(r.get()) == 0) break;
      for (int i = 0; i < PQntuples(r.get()); ++i) visit(region_row(r.get(), i));
    }
    exec("COMMIT");
  } catch (...) {
    Result rollback(PQexec(db_, "ROLLBACK"), &PQclear);
    throw;
  }
}

void PostgresRegionStore::require_owned(const TreePath& path) {
  if (server_.empty()) return;
  Params p;
  p.binary(bytes_of(path));
  p.text(server_);
  const Result r =
      run(db_, "SELECT epoch FROM owners WHERE path = $1 AND server = $2 FOR UPDATE", p);
  if (PQntuples(r.get()) == 0)
    throw StoreError("postgres commit: a region " + server_ + " does not own");
}

void PostgresRegionStore::commit(const std::vector<StoredRegion>& regions,
                                 const std::optional<WorldRecord>& world) {
  exec("BEGIN");
  try {
    for (const StoredRegion& row : regions) {
      require_owned(row.path);
      run(db_, kPutRegion, region_params(row));
    }
    if (world) run(db_, kPutWorld, world_params(*world));
    exec("COMMIT");
  } catch (...) {
    Result rollback(PQexec(db_, "ROLLBACK"), &PQclear);
    throw;
  }
}

std::vector<TreePath> PostgresRegionStore::claim(const std::vector<TreePath>& paths) {
  for (const TreePath& path : paths) {
    Params p;
    p.binary(bytes_of(path));
    p.text(server_);
    run(db_, "INSERT INTO owners (path, server, epoch) VALUES ($1, $2, 1) ON CONFLICT DO NOTHING",
        p);
  }
  Params p;
  p.text(server_);
  const Result r = run(db_, "SELECT path FROM owners WHERE server = $1 ORDER BY path", p);
  std::vector<TreePath> owned;
  for (int i = 0; i < PQntuples(r.get()); ++i) owned.push_back(path_of(bytea_at(r.get(), i, 0)));
  return owned;
}

std::string PostgresRegionStore::owner(const TreePath& path) {
  Params p;
  p.binary(bytes_of(path));
  const Result r = run(db_, "SELECT server FROM owners WHERE path = $1", p);
  return PQntuples(r.get()) == 0 ? std::string() : bytea_at(r.get(), 0, 0);
}

void PostgresRegionStore::hand_over(const StoredRegion& last, const std::string& to) {
  exec("BEGIN");
  try {
    require_owned(last.path);
    run(db_, kPutRegion, region_params(last));
    Params p;
    p.binary(bytes_of(last.path));
    p.text(to);
    run(db_, "UPDATE owners SET server = $2, epoch = epoch + 1 WHERE path = $1", p);
    exec("COMMIT");
  } catch (...) {
    Result rollback(PQexec(db_, "ROLLBACK"), &PQclear);
    throw;
  }
}

}  // namespace edgeland::store
