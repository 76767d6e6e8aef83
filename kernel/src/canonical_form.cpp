#include "edgeland/kernel/canonical_form.hpp"

#include <algorithm>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland {
namespace {

const char* rule_text(CanonicalRule rule) {
  switch (rule) {
    case CanonicalRule::kNotStartingAtSmallest:
      return "not-starting-at-smallest-vertex";
    case CanonicalRule::kCollinearVertex:
      return "collinear-vertex";
    case CanonicalRule::kNotSorted:
      return "not-sorted";
    case CanonicalRule::kTooFewVertices:
      return "too-few-vertices";
  }
  return "unknown-rule";  // Not reached by tests: the switch covers every rule.
}

std::optional<CanonicalViolation> ring_violation(const Polygon& ring, std::size_t index) {
  const std::size_t n = ring.size();
  if (n < 3)
    return CanonicalViolation{CanonicalRule::kTooFewVertices, index, n ? ring[0] : Point64{}};
  const auto smallest = std::min_element(ring.begin(), ring.end());
  if (smallest != ring.begin())
    return CanonicalViolation{CanonicalRule::kNotStartingAtSmallest, index, *smallest};
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
    if (orientation(prev, v, next) == Orientation::kCollinear)
      return CanonicalViolation{CanonicalRule::kCollinearVertex, index, v};
  }
  return std::nullopt;
}

}  // namespace

std::string CanonicalViolation::describe() const {
  return std::string(rule_text(rule)) + ": polygon " + std::to_string(polygon) + " at (" +
         std::to_string(where.x) + " " + std::to_string(where.y) + ")";
}

std::optional<CanonicalViolation> canonical_violation(const PolygonSet& set) noexcept {
  for (std::size_t k = 0; k < set.size(); ++k) {
    if (auto v = ring_violation(set[k], k)) return v;
    if (k > 0 && set[k].front() < set[k - 1].front())
      return CanonicalViolation{CanonicalRule::kNotSorted, k, set[k].front()};
  }
  return std::nullopt;
}

}  // namespace edgeland
