// check_assembled (stage_checks.hpp): assembly's promises to hole splitting, canonical ordering
// and the caller.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "stage_check_text.hpp"
#include "stage_checks.hpp"

namespace edgeland::detail {
namespace {

constexpr const char* kStage = "assembly";

std::string num(std::size_t i) { return std::to_string(i); }

// Closed implicitly, at least 3 points, no zero-length edge, the orientation its role asks.
// which() names the ring in messages (built only on failure: most rings are small).
template <class Which>
void check_ring_shape(const Ring& ring, Orientation expected, const Which& which) {
  const std::size_t n = ring.size();
  if (n < 3) fail_stage(kStage, "ring size: " + which() + " has " + num(n) + " points");
  if (ring.front() == ring.back())
    fail_stage(kStage, "closing point repeated: " + which() + " ends with its first point " +
                           text(ring.front()));
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (ring[i] == ring[i + 1])
      fail_stage(kStage, "repeated consecutive point: " + which() + " repeats " + text(ring[i]) +
                             " at " + num(i));
  const Orientation o = ring_orientation(ring);
  if (o != expected)
    fail_stage(kStage, "orientation: " + which() + " is " +
                           (o == Orientation::kCollinear   ? "of zero area"
                            : o == Orientation::kClockwise ? "clockwise"
                                                           : "counter-clockwise"));
}

// A simple loop: no point twice. O(n log n).
template <class Which>
void check_no_repeated_point(const Ring& ring, const Which& which) {
  std::vector<Point64> sorted = ring;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end())
    fail_stage(kStage, "repeated point: " + which() + " visits " + text(*twice) + " twice");
}

// Canonical form of one ring (canonical.hpp): smallest point first, no collinear vertex.
template <class Which>
void check_canonical(const Ring& ring, const Which& which) {
  const std::size_t n = ring.size();
  const auto smallest = std::min_element(ring.begin(), ring.end());
  if (smallest != ring.begin())
    fail_stage(kStage, "canonical: " + which() + " starts at " + text(ring.front()) +
                           ", not at its smallest point " + text(*smallest));
  for (std::size_t i = 0; i < n; ++i)
    if (orientation(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) == Orientation::kCollinear)
      fail_stage(kStage, "canonical: " + which() + " has a vertex " + text(ring[i]) +
                             " collinear with its neighbours");
}

void check_output_rings(const Assembled& a) {
  if (a.labels.size() != a.rings.size())
    fail_stage(kStage,
               "labels: " + num(a.labels.size()) + " labels for " + num(a.rings.size()) + " rings");
  for (std::size_t r = 0; r < a.rings.size(); ++r) {
    auto which = [&] { return "ring " + num(r) + " (label " + std::to_string(a.labels[r]) + ")"; };
    if (a.labels[r] < 0) fail_stage(kStage, "labels: " + which() + " has a negative label");
    check_ring_shape(a.rings[r], Orientation::kCounterClockwise, which);
    check_no_repeated_point(a.rings[r], which);
    check_canonical(a.rings[r], which);
  }
}

void check_region(const RegionRings& region, std::size_t index) {
  auto which = [&] {
    return "holed region " + num(index) + " (label " + std::to_string(region.label) + ")";
  };
  if (region.label < 0) fail_stage(kStage, "holed region: " + which() + " has a negative label");
  if (region.outers.empty() || region.holes.empty())
    fail_stage(kStage, "holed region: " + which() + " has " + num(region.outers.size()) +
                           " outer rings and " + num(region.holes.size()) + " holes");
  for (std::size_t r = 0; r < region.outers.size(); ++r) {
    auto outer = [&] { return "outer " + num(r) + " of " + which(); };
    check_ring_shape(region.outers[r], Orientation::kCounterClockwise, outer);
    check_no_repeated_point(region.outers[r], outer);
  }
  for (std::size_t r = 0; r < region.holes.size(); ++r) {
    auto hole = [&] { return "hole " + num(r) + " of " + which(); };
    check_ring_shape(region.holes[r], Orientation::kClockwise, hole);
    check_no_repeated_point(region.holes[r], hole);
  }
}

}  // namespace

void check_assembled(const Assembled& assembled) {
  check_output_rings(assembled);
  const auto& holed = assembled.holed;
  for (std::size_t i = 0; i < holed.size(); ++i) {
    check_region(holed[i], i);
    if (i > 0 && holed[i - 1].label >= holed[i].label)
      fail_stage(kStage, "holed order: holed region " + num(i) + " (label " +
                             std::to_string(holed[i].label) + ") follows label " +
                             std::to_string(holed[i - 1].label));
  }
}

}  // namespace edgeland::detail
