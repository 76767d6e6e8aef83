// The server's decisions on a client's requests (request_checks.hpp).
#include "edgeland/net/request_checks.hpp"

#include <algorithm>
#include <vector>

#include "edgeland/spatial/delta.hpp"

namespace edgeland::net {
namespace {

// The delta read, or why it cannot be: each typed error of decode_delta has its reason.
std::optional<Delta> read_delta(std::string_view bytes, Refusal& refusal) {
  try {
    return decode_delta(bytes);
  } catch (const DeltaError& e) {
    refusal = {RejectReason::kMalformed, e.what()};
  } catch (const CoordinateOutOfRange& e) {
    refusal = {RejectReason::kOutOfRange, e.what()};
  } catch (const InvalidInput& e) {
    refusal = {RejectReason::kInvalidShape, e.what()};
  }
  return std::nullopt;
}

// In tree order the paths inside a path come right after it, so a path given twice or inside
// another lies within its predecessor (as a PATCH's entries must not: patch.cpp).
bool distinct_and_apart(std::vector<TreePath> paths) {
  std::sort(paths.begin(), paths.end(), path_less);
  for (std::size_t i = 1; i < paths.size(); ++i)
    if (path_within(paths[i], paths[i - 1])) return false;
  return true;
}

}  // namespace

EditVerdict check_edit_request(const Landscape& world, const Box64& granted,
                               const EditPolicy& policy, std::string_view delta) {
  EditVerdict verdict;
  if (delta.size() > policy.max_message) {
    verdict.refusal = {RejectReason::kTooLarge, "message over the limit"};
    return verdict;
  }
  std::optional<Delta> d = read_delta(delta, verdict.refusal);
  if (!d) return verdict;
  if (d->header.kind != DeltaKind::kCommand || d->header.world != world.world_hash() ||
      d->header.algorithm != kAlgorithmVersion) {
    verdict.refusal = {RejectReason::kOtherWorld, "not a COMMAND of this world and version"};
    return verdict;
  }
  for (const Edit& edit : d->edits) {
    const std::optional<Box64> box = bounding_box(edit.shape.polygons());
    if (box && !permitted(granted, *box)) {
      verdict.refusal = {RejectReason::kNotPermitted, "outside the box granted"};
      return verdict;
    }
  }
  verdict.edits = std::move(d->edits);
  return verdict;
}

std::optional<ChangeSet> apply_accepted(Landscape& world, std::span<const Edit> edits,
                                        Refusal& refusal) {
  try {
    return world.apply_batch(edits);
  } catch (const LimitExceeded& e) {
    const bool shape = e.limit == LimitExceeded::Limit::kShapeVertices;
    refusal = {shape ? RejectReason::kTooLarge : RejectReason::kLimit, e.what()};
    return std::nullopt;
  }
}

std::optional<Refusal> check_repair_request(const Landscape& world, std::span<const TreePath> paths,
                                            bool patch, const EditPolicy& policy,
                                            const std::function<bool(const TreePath&)>& may_ask) {
  if (paths.size() > policy.max_repair_paths)
    return Refusal{RejectReason::kTooLarge, "more paths than a repair request may hold"};
  for (const TreePath& p : paths)
    if (!may_ask(p)) return Refusal{RejectReason::kNotPermitted, "a path not watched"};
  if (!patch) return std::nullopt;
  for (const TreePath& p : paths)
    if (!world.node_digest(p)) return Refusal{RejectReason::kMalformed, "a path to no node"};
  if (!distinct_and_apart(std::vector<TreePath>(paths.begin(), paths.end())))
    return Refusal{RejectReason::kMalformed, "a path twice, or inside another"};
  return std::nullopt;
}

}  // namespace edgeland::net
