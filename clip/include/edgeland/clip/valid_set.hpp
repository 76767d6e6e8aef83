#pragma once
// ValidSet: a polygon set known to be valid (clip.hpp's operations take and return it).
#include <cstddef>
#include <span>
#include <utility>

#include "edgeland/clip/types.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

struct BoxedSet;  // below: the parts join() puts together

// A polygon set known to be valid, so that operations on it need not validate it again: a game
// that carves one set thousands of times pays for validation once, when the set is built, not
// on every operation (validation is O(n log n) in the whole set, the operation near-linear in
// the part that changes). Constructed only by validating (throws InvalidInput) or as the output
// of an operation of clip.hpp or relabel.hpp, which is valid by their guarantee (re-checked in
// checked mode). Immutable: the only way to change it is another operation.
class EDGELAND_EXPORT ValidSet {
 public:
  ValidSet() = default;  // the empty set
  // Validates `set`; throws InvalidInput naming `which` operand on the first violation.
  explicit ValidSet(PolygonSet set, Operand which = Operand::kSubject);
  const PolygonSet& polygons() const noexcept { return set_; }
  PolygonSet release() && noexcept { return std::move(set_); }

 private:
  struct Trusted {};
  ValidSet(PolygonSet set, Trusted) noexcept : set_(std::move(set)) {}
  friend struct ValidSetFactory;
  friend ValidSet subset(const ValidSet& set, std::span<const std::size_t> members);
  friend ValidSet join(std::span<const BoxedSet> parts);
  PolygonSet set_;
  bool canonical_ = false;  // in canonical form (an operation's output)
  // No ring has three consecutive collinear vertices (canonical sets, and validated sets found
  // so): the pipeline then tests only the vertices an operation creates for collinearity.
  bool collinear_free_ = false;
};

// The members of `set` at these indices (ascending, each at most once), in their order: valid
// without validating again (any part of a valid set is one), and in canonical form when `set`
// is. Throws InvalidArgument for an index out of range or out of order.
EDGELAND_EXPORT ValidSet subset(const ValidSet& set, std::span<const std::size_t> members);

// A part of a set being put together: a valid set, and a box its members should lie in.
struct BoxedSet {
  const ValidSet* set = nullptr;
  Box64 box;
};

// The members of the parts, in order, as one valid set. When every member lies in its part's
// (closed) box and no two boxes' interiors meet (a landscape's cells, a grid's tiles), members of
// different parts cannot overlap, and nothing is validated again: O(n) for the members' boxes
// and O(k log k) for the k boxes. Otherwise the members are validated together, as ValidSet's
// constructor does (InvalidInput on the first violation). A part whose set is null is empty.
EDGELAND_EXPORT ValidSet join(std::span<const BoxedSet> parts);

struct ValidClipResult {
  ValidSet set;
  ClipStats stats;
};

}  // namespace edgeland
