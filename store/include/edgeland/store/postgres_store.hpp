#pragma once
// The shared region store (store/README.md, "Beyond one server"): the same tables in a PostgreSQL
// database through libpq, and an `owners` table saying which server owns which region. A store
// opened with a server name commits only regions that server owns (checked in the commit's own
// transaction, so a server that lost a region cannot write it again).
#include <cstdint>
#include <string>
#include <vector>

#include "edgeland/store/region_store.hpp"

struct pg_conn;

namespace edgeland::store {

class EDGELAND_EXPORT PostgresRegionStore : public RegionStore {
 public:
  // Connects (libpq `conninfo`, e.g. "host=/tmp/dir port=5432 user=postgres") and creates the
  // tables when missing. `server`: this writer's name in `owners` (empty: no ownership checks, a
  // store used by one writer or only read). Throws StoreError.
  explicit PostgresRegionStore(const std::string& conninfo, std::string server = {});
  ~PostgresRegionStore() override;
  PostgresRegionStore(const PostgresRegionStore&) = delete;
  PostgresRegionStore& operator=(const PostgresRegionStore&) = delete;

  std::optional<WorldRecord> world() override;
  std::optional<StoredRegion> region(const TreePath& path) override;
  void for_each_region(const std::function<void(const StoredRegion&)>& visit) override;
  // With a server name: every region must be owned by this server (StoreError otherwise, and
  // nothing is written). The world row keeps the larger next id and sequence number of the two.
  void commit(const std::vector<StoredRegion>& regions,
              const std::optional<WorldRecord>& world) override;

  // Claims the regions of `paths` that nobody owns yet; returns every region this server owns
  // now, in path order.
  std::vector<TreePath> claim(const std::vector<TreePath>& paths);
  // The owner of a region ("" when none).
  std::string owner(const TreePath& path);
  // Hands a region this server owns to `to`: its last record and the change of owner (epoch + 1)
  // in one transaction. Afterwards this server must drop the region; `to` loads it from here.
  void hand_over(const StoredRegion& last, const std::string& to);

 private:
  void exec(const char* sql);
  void require_owned(const TreePath& path);
  pg_conn* db_ = nullptr;
  std::string server_;
};

}  // namespace edgeland::store
