#pragma once
// Private to validate_*.cpp: the rules of validate.hpp, one function per kind of check.
// Each reports into a ViolationSink, which keeps at most the caller's maximum.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"
#include "validate_report_sweep.hpp"

namespace edgeland::detail {

// Collects violations up to a maximum (at least one, so an invalid input never looks valid).
class ViolationSink {
 public:
  explicit ViolationSink(std::size_t max_violations)
      : max_(std::max<std::size_t>(max_violations, 1)) {}
  bool full() const noexcept { return violations_.size() >= max_; }
  void add(const Violation& v) {
    if (!full()) violations_.push_back(v);
  }
  std::vector<Violation> take() { return std::move(violations_); }

 private:
  std::size_t max_;
  std::vector<Violation> violations_;
};

// Vertex count, coordinate range and repeated consecutive vertices: O(n). Returns whether the
// ring passed, i.e. whether its edges may be handed to the geometric checks.
bool check_ring_structure(const Ring& ring, std::size_t polygon, ViolationSink& sink);

// Adjacent edges folding back onto each other, found at their common vertex: O(n).
// Returns whether the ring has none.
bool check_spikes(const Ring& ring, std::size_t polygon, ViolationSink& sink);

// Positive area for a simple ring: O(n). Returns whether the ring is counter-clockwise.
bool check_orientation(const Ring& ring, std::size_t polygon, ViolationSink& sink);

// The first pair of non-adjacent edges of one ring (its `edges`, built by append_ring_edges
// and sort_for_sweep) that share a point, found by the sweep in O(n log n). Needs a ring that
// passed the structure check; spikes are allowed (they are a separate rule).
std::optional<Violation> find_self_intersection(const std::vector<SweepEdge>& edges,
                                                std::size_t ring_size);

// Whether `polygons` is a valid polygon set, proven by the local rules of each ring and one
// sweep over all edges (validate_accept_sweep.cpp): O(n log n), and cheaper than the checks below.
// True only for a valid input; false means invalid or undecided, and reports nothing: the
// checks below then find and report what is wrong.
bool accepted_by_one_sweep(std::span<const Polygon> polygons);
// The same for the set of polygons[i] for i in `members`.
bool accepted_by_one_sweep(std::span<const Polygon> polygons, std::span<const std::size_t> members);

// The first pair of rings whose interiors overlap, found by the sweep in O(n log n). Needs
// rings that are each strictly simple and counter-clockwise, edges sorted by sort_for_sweep.
std::optional<Violation> find_overlap(const std::vector<SweepEdge>& edges);

}  // namespace edgeland::detail
