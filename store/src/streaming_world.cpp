// StreamingWorld (streaming_world.hpp): regions in on demand, out by least recent use.
#include "edgeland/store/streaming_world.hpp"

#include <algorithm>

#include "edgeland/spatial/delta.hpp"

namespace edgeland::store {

StreamingWorld::StreamingWorld(RegionStore& store, std::size_t budget,
                               const LandscapeLimits& limits)
    : store_(store), budget_(budget), world_(open_world(store, limits, &seen_)) {
  seq_ = seen_.empty()
             ? 0
             : std::min_element(seen_.begin(), seen_.end(), [](const auto& a, const auto& b) {
                 return a.second < b.second;
               })->second;
  // Regions that have seen an edit stay unloaded for it, and the edit passes over them.
  world_.set_unloaded_policy(UnloadedRegions::kSkip);
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
  std::vector<TreePath> paths;
  // A region that has seen this edit is not loaded for it: every region that is loaded has
  // seen only earlier edits.
  for (const TreePath& p : box ? world_.regions_meeting(*box) : std::vector<TreePath>{})
    if (seen_[p] <= seq_) paths.push_back(p);
  bring_in(paths);
  std::vector<std::uint64_t> before;
  for (const TreePath& p : paths) before.push_back(world_.node_digest(p)->hash);
  ChangeSet changes = apply_edit(world_, edit);
  ++seq_;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    seen_[paths[i]] = seq_;
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
    if (l.dirty) rows.push_back(stored_region(world_, *it, seen_[*it]));
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
    if (l.dirty) rows.push_back(stored_region(world_, p, seen_[p]));
  store_.commit(rows, record());
  ++stats_.commits;
  stats_.writes += rows.size();
  for (auto& [p, l] : loaded_) l.dirty = false;
}

}  // namespace edgeland::store
