// Applying deltas (Landscape::apply_delta, apply_edit) and the world's own hash.
#include "edgeland/spatial/delta.hpp"
#include "edit_form.hpp"
#include "patch.hpp"
#include "regions.hpp"
#include "state_hash.hpp"

namespace edgeland {

ChangeSet apply_edit(Landscape& world, const Edit& e) {
  using Kind = Edit::Kind;
  if (!detail::has_its_form(e)) return world.relabel(e.shape, e.map);
  switch (e.kind) {
    case Kind::kCarve:
      return world.carve(e.shape);
    case Kind::kFill:
      return world.fill(e.shape, e.map[kEmpty]);
    case Kind::kFillEmpty:
      return world.fill_empty(e.shape, e.map[kEmpty]);
    case Kind::kReplace: {
      const auto [from, to] = detail::replaced(e.map);
      return world.replace(e.shape, from, to);
    }
    case Kind::kRelabel:
      break;
  }
  return world.relabel(e.shape, e.map);
}

std::uint64_t Landscape::world_hash() const noexcept {
  detail::StateHash h;
  detail::add_world(h, s_.world, s_.config);
  return h.value();
}

namespace {

ChangeSet apply_command(Landscape& next, const Delta& d) {
  if (d.header.algorithm != kAlgorithmVersion)
    throw DeltaMismatch(DeltaMismatch::Field::kAlgorithm, d.header.algorithm, kAlgorithmVersion);
  if (d.edits.empty()) throw DeltaError("a command of no edit", 0);
  return next.apply_batch(d.edits);  // one edit: apply_edit
}

}  // namespace

// The result is built apart (a copy costs O(1)) and kept by one assignment once every check
// passed.
ChangeSet Landscape::apply_delta(const Delta& d, const DeltaChecks& checks) {
  if (d.header.world != world_hash())
    throw DeltaMismatch(DeltaMismatch::Field::kWorld, d.header.world, world_hash());
  if (checks.base && d.header.base != state_hash())
    throw DeltaMismatch(DeltaMismatch::Field::kBase, d.header.base, state_hash());
  Landscape next = *this;
  ChangeSet changes;
  switch (d.header.kind) {
    case DeltaKind::kCommand:
      changes = apply_command(next, d);
      break;
    case DeltaKind::kPatch: {
      detail::EditResult patched = detail::apply_patch(s_, d);
      next.s_ = std::move(patched.next);
      changes = std::move(patched.changes);
      break;
    }
    case DeltaKind::kChanges:
      throw DeltaError("a CHANGES delta is for a DrawMirror, not a landscape", 0);
  }
  if (checks.result && next.state_hash() != d.header.result)
    throw DeltaMismatch(DeltaMismatch::Field::kResult, d.header.result, next.state_hash());
  *this = std::move(next);
  return changes;
}

}  // namespace edgeland
