// A world's regions as rows of a region store (region_store.hpp).
#include <sstream>

#include "edgeland/store/region_store.hpp"

namespace edgeland::store {

StoredRegion stored_region(const Landscape& world, const TreePath& path, std::uint64_t seq) {
  std::ostringstream out;
  world.save_region(path, out);
  return StoredRegion{path, std::move(out).str(), world.region_summary(path).hash, seq};
}

void write_world(RegionStore& store, const Landscape& world, std::uint64_t seq) {
  std::vector<StoredRegion> rows;
  for (const TreePath& path : world.region_paths()) rows.push_back(stored_region(world, path, seq));
  store.commit(rows, WorldRecord{world.world(), world.config(), world.next_id(), seq});
}

Landscape open_world(RegionStore& store, const LandscapeLimits& limits) {
  const std::optional<WorldRecord> w = store.world();
  if (!w) throw StoreError("the store holds no world");
  std::vector<RegionSummary> summaries;
  store.for_each_region([&](const StoredRegion& row) {
    std::istringstream in(row.record);
    summaries.push_back(Landscape::read_region_summary(in));
    if (summaries.back().path != row.path || summaries.back().hash != row.hash)
      throw StoreError("the region row's path or hash is not its record's");
  });
  return Landscape::from_regions(w->world, w->config, w->next_id, summaries, limits);
}

void load_region(RegionStore& store, Landscape& world, const TreePath& path) {
  const std::optional<StoredRegion> row = store.region(path);
  if (!row) throw StoreError("the store holds no such region");
  std::istringstream in(row->record);
  world.load_region(in);
}

}  // namespace edgeland::store
