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

Landscape open_world(RegionStore& store, const LandscapeLimits& limits,
                     std::map<TreePath, std::uint64_t>* seqs) {
  const std::optional<WorldRecord> w = store.world();
  if (!w) throw StoreError("the store holds no world");
  std::vector<RegionSummary> summaries;
  store.for_each_region([&](const StoredRegion& row) {
    std::istringstream in(row.record);
    summaries.push_back(Landscape::read_region_summary(in));
    if (summaries.back().path != row.path || summaries.back().hash != row.hash)
      throw StoreError("the region row's path or hash is not its record's");
    if (seqs) (*seqs)[row.path] = row.seq;
  });
  return Landscape::from_regions(w->world, w->config, w->next_id, summaries, limits);
}

std::array<std::int64_t, 13> world_columns(const WorldRecord& w) {
  const LandscapeConfig& c = w.config;
  return {w.world.min.x,
          w.world.min.y,
          w.world.max.x,
          w.world.max.y,
          static_cast<std::int64_t>(c.tree),
          std::int64_t{c.edge_cap},
          std::int64_t{c.merge_below},
          c.min_cell_size,
          std::int64_t{c.grid_depth},
          std::int64_t{c.region_depth},
          std::int64_t{c.region_ids ? 1 : 0},
          static_cast<std::int64_t>(w.next_id),
          static_cast<std::int64_t>(w.seq)};
}

WorldRecord world_of_columns(const std::array<std::int64_t, 13>& v) {
  WorldRecord w;
  w.world = {{v[0], v[1]}, {v[2], v[3]}};
  LandscapeConfig& c = w.config;
  c.tree = static_cast<TreeKind>(v[4]);
  c.edge_cap = static_cast<std::uint32_t>(v[5]);
  c.merge_below = static_cast<std::uint32_t>(v[6]);
  c.min_cell_size = v[7];
  c.grid_depth = static_cast<int>(v[8]);
  c.region_depth = static_cast<int>(v[9]);
  c.region_ids = v[10] != 0;
  w.next_id = static_cast<PolygonId>(v[11]);
  w.seq = static_cast<std::uint64_t>(v[12]);
  return w;
}

void load_region(RegionStore& store, Landscape& world, const TreePath& path) {
  const std::optional<StoredRegion> row = store.region(path);
  if (!row) throw StoreError("the store holds no such region");
  std::istringstream in(row->record);
  world.load_region(in);
}

}  // namespace edgeland::store
