// StreamingWorld (streaming_world.hpp): regions in on demand, out by least recent use.
#include "edgeland/store/streaming_world.hpp"

#include "edgeland/spatial/delta.hpp"

namespace edgeland::store {

StreamingWorld::StreamingWorld(RegionStore& store, std::size_t budget, const LandscapeLimits& limits)
    : store_(store), budget_(budget), world_(open_world(store, limits)) {
  seq_ = store_.world()->seq;
}

WorldRecord StreamingWorld::record() const {
  return WorldRecord{world_.world(), world_.config(), world_.next_id(), seq_};
}

void StreamingWorld::bring_in(const std::vector<TreePath>& paths) {
  for (const TreePath& p : paths) {
    if (loaded_.count(p)) continue;
    load_region(store_, world_, p);
    ++stats_.loads;
    lru_.push_back(p);
    loaded_[p] = Loaded{world_.region_bytes(p), false, std::prev(lru_.end())};
    stats_.loaded_bytes += loaded_[p].bytes;
  }
}

ChangeSet StreamingWorld::apply(const Edit& edit) {
  const std::optional<Box64> box = bounding_box(edit.shape.polygons());
  const std::vector<TreePath> paths = box ? world_.regions_meeting(*box) : std::vector<TreePath>{};
  bring_in(paths);
  std::vector<std::uint64_t> before;
  for (const TreePath& p : paths) before.push_back(world_.node_digest(p)->hash);
  ChangeSet changes = apply_edit(world_, edit);
  ++seq_;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    Loaded& l = loaded_[paths[i]];
    lru_.splice(lru_.end(), lru_, l.at);
    if (world_.node_digest(paths[i])->hash == before[i]) continue;
    l.dirty = true;
    stats_.loaded_bytes -= l.bytes;
    l.bytes = world_.region_bytes(paths[i]);
    stats_.loaded_bytes += l.bytes;
  }
  evict_to_budget();
  return changes;
}

// The dirty regions evicted now are committed together (with the world's row) before any of
// them is unloaded: a failed commit loses nothing.
void StreamingWorld::evict_to_budget() {
  std::vector<TreePath> out;
  std::vector<StoredRegion> rows;
  std::size_t bytes = stats_.loaded_bytes;
  for (auto it = lru_.begin(); bytes > budget_ && it != lru_.end(); ++it) {
    const Loaded& l = loaded_[*it];
    if (l.dirty) rows.push_back(stored_region(world_, *it, seq_));
    bytes -= l.bytes;
    out.push_back(*it);
  }
  if (!rows.empty()) {
    store_.commit(rows, record());
    stats_.writes += rows.size();
    ++stats_.commits;
  }
  for (const TreePath& p : out) {
    world_.unload_region(p);
    lru_.erase(loaded_[p].at);
    loaded_.erase(p);
    ++stats_.evictions;
  }
  stats_.loaded_bytes = bytes;
  stats_.peak_loaded_bytes = std::max(stats_.peak_loaded_bytes, bytes);
}

void StreamingWorld::flush() {
  std::vector<StoredRegion> rows;
  for (const auto& [p, l] : loaded_)
    if (l.dirty) rows.push_back(stored_region(world_, p, seq_));
  store_.commit(rows, record());
  ++stats_.commits;
  stats_.writes += rows.size();
  for (auto& [p, l] : loaded_) l.dirty = false;
}

}  // namespace edgeland::store
