#pragma once
// The embedded region store (store/README.md): one SQLite database file, WAL mode with
// synchronous=FULL, so a commit that returned survives a crash of the writer.
#include <memory>
#include <string>

#include "edgeland/store/region_store.hpp"

struct sqlite3;

namespace edgeland::store {

class EDGELAND_EXPORT SqliteRegionStore : public RegionStore {
 public:
  // Opens (creating it and its tables when missing) the database at `path`. Throws StoreError.
  explicit SqliteRegionStore(const std::string& path);
  ~SqliteRegionStore() override;
  SqliteRegionStore(const SqliteRegionStore&) = delete;
  SqliteRegionStore& operator=(const SqliteRegionStore&) = delete;

  std::optional<WorldRecord> world() override;
  std::optional<StoredRegion> region(const TreePath& path) override;
  void for_each_region(const std::function<void(const StoredRegion&)>& visit) override;
  void commit(const std::vector<StoredRegion>& regions,
              const std::optional<WorldRecord>& world) override;
  // SQLite's own check of the file ("ok" when sound).
  std::string integrity_check();

 private:
  void exec(const char* sql);
  sqlite3* db_ = nullptr;
};

}  // namespace edgeland::store
