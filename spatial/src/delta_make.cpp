// Deltas from landscapes (delta.hpp): a COMMAND from an edit and its result, a PATCH of
// subtrees, CHANGES from a change set.
#include "edgeland/spatial/delta.hpp"

namespace edgeland {
namespace {

DeltaHeader header_of(DeltaKind kind, const Landscape& before, std::uint64_t base,
                      const Landscape& after, std::uint64_t sequence) {
  return DeltaHeader{kind, kAlgorithmVersion, before.world_hash(), sequence,
                     base, after.state_hash()};
}

}  // namespace

Delta command_delta(const Landscape& before, const Landscape& after, std::uint64_t sequence,
                    const Edit& edit) {
  return command_delta(before, after, sequence, std::span(&edit, 1));
}

Delta command_delta(const Landscape& before, const Landscape& after, std::uint64_t sequence,
                    std::span<const Edit> batch) {
  Delta d;
  d.header = header_of(DeltaKind::kCommand, before, before.state_hash(), after, sequence);
  d.edits.assign(batch.begin(), batch.end());
  return d;
}

Delta patch_delta(const Landscape& source, std::uint64_t sequence,
                  const std::vector<TreePath>& paths, std::uint64_t base) {
  Delta d;
  d.header = header_of(DeltaKind::kPatch, source, base, source, sequence);
  d.next_id = source.next_id();
  for (const TreePath& p : paths) d.patches.push_back(source.patch_entry(p));
  return d;
}

Delta changes_delta(const Landscape& before, const Landscape& after, std::uint64_t sequence,
                    const ChangeSet& changes) {
  Delta d;
  d.header = header_of(DeltaKind::kChanges, before, before.state_hash(), after, sequence);
  d.removed = changes.removed;
  for (const ChangeSet::Added& a : changes.added)
    d.added.push_back(DrawnPolygon{a.id, a.material, a.polygon});
  return d;
}

}  // namespace edgeland
