#pragma once
// What the server decides about a client's requests (net/README.md, "Reject reasons"): from an
// EDIT's delta bytes to the edit to apply or the typed reason it is refused, the application of
// an accepted edit, and whether a repair request may be answered. The server and the fuzz
// target of its input (fuzz/net_decoders.cpp) run these same decisions. Rates are the caller's
// (they need a clock).
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/net/edit_policy.hpp"
#include "edgeland/net/protocol.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::net {

// Why a request is refused: the reason a REJECT carries and the typed error's message.
struct Refusal {
  RejectReason reason = RejectReason::kMalformed;
  std::string message;
};

// The edits of a COMMAND accepted (one edit, or a frame batch: Landscape::apply_batch), or why
// not (`edits` empty).
struct EditVerdict {
  std::vector<Edit> edits;
  Refusal refusal;
  bool accepted() const { return !edits.empty(); }
};

// The message size against the policy, then the delta read (DeltaError: malformed,
// CoordinateOutOfRange: out of range, InvalidInput: invalid shape), its kind, world and
// algorithm version (another world), and every edit's shape box against the box granted (not
// permitted: one edit of a batch outside refuses the whole batch). Never throws but
// std::bad_alloc. O(the delta).
EDGELAND_EXPORT EditVerdict check_edit_request(const Landscape& world, const Box64& granted,
                                               const EditPolicy& policy, std::string_view delta);

// Applies accepted edits as the COMMAND's receivers will (apply_batch; a batch of one is
// apply_edit): the change set, or the refusal when the world would pass its limits
// (LimitExceeded: a shape's vertices, too large; the world's, limit), the world then unchanged.
// Throws what apply_batch throws otherwise (a bug: LandscapeInternalError).
EDGELAND_EXPORT std::optional<ChangeSet> apply_accepted(Landscape& world,
                                                        std::span<const Edit> edits,
                                                        Refusal& refusal);

// Whether the paths of a HASHES (`patch` false) or PATCH_REQUEST (`patch` true) may be answered:
// at most policy.max_repair_paths, each one `may_ask` allows (the client's regions); a patch's
// paths must be nodes of the world, distinct, and none inside another, so its answer holds each
// node at most once (never more than a save of the world). nullopt: answer it. O(paths x depth).
EDGELAND_EXPORT std::optional<Refusal> check_repair_request(
    const Landscape& world, std::span<const TreePath> paths, bool patch, const EditPolicy& policy,
    const std::function<bool(const TreePath&)>& may_ask);

}  // namespace edgeland::net
