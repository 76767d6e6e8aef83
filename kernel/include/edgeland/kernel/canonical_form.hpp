#pragma once
// The canonical form of polygon sets, the order every clipper output is written in (clip.hpp,
// CANONICAL OUTPUT), checked from its definition: each ring starts at its lexicographically
// smallest vertex and has no collinear consecutive vertices (around the whole ring), and the
// rings are sorted by their first vertex. It is a property of a set's order and is checked
// apart from validity: validate() (validate.hpp) checks that; an output meets both.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

enum class CanonicalRule : std::uint8_t {
  kNotStartingAtSmallest,  // a ring's first vertex is not its smallest
  kCollinearVertex,        // a vertex lies on the line through its two neighbours
  kNotSorted,              // a ring's first vertex is smaller than the previous ring's
  kTooFewVertices,         // a ring has fewer than 3 vertices (no ring to speak of)
};

struct CanonicalViolation {
  CanonicalRule rule = CanonicalRule::kNotStartingAtSmallest;
  std::size_t polygon = 0;  // the ring (for kNotSorted: the later of the two)
  Point64 where;            // the vertex concerned (kNotSorted: the ring's first vertex)
  // One line, e.g. "collinear-vertex: polygon 2 at (5 0)".
  EDGELAND_EXPORT std::string describe() const;
};

// The first departure of `set` from the canonical form, in ring order; nullopt when there is
// none. Exact, O(n) for n vertices in all; works on any set (invalid ones too).
EDGELAND_EXPORT std::optional<CanonicalViolation> canonical_violation(
    const PolygonSet& set) noexcept;

inline bool is_canonical(const PolygonSet& set) noexcept { return !canonical_violation(set); }

}  // namespace edgeland
