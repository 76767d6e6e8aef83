#pragma once
// Private to validate_*.cpp: the first try of validate()'s fast acceptance path, a sweep over
// monotone runs of edges instead of over every vertex (validate_monotone_runs.cpp).
//
// Each ring is cut into runs: maximal stretches of consecutive edges that never turn back in x
// nor in y (capped at a few edges, so their boxes stay tight). A run's box is the box of its
// two end vertices, two edges of one run meet only if they are ring neighbours, and two runs
// whose edges meet have boxes that meet. So sorting the runs (n / cap of them on a smooth
// ring) and testing the edges of box-overlapping runs settles a smooth input in little more
// than the O(n) pass over its vertices that the local rules need anyway.
#include <cstddef>
#include <cstdint>
#include <span>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

enum class RunVerdict : std::uint8_t {
  kValid,      // the input is a valid polygon set
  kInvalid,    // it is not (a local rule fails, or two edges meet as they must not)
  kUndecided,  // every local rule holds, but the run sweep does not decide: ask the vertex sweep
  kNotTried,   // rings too small on average for runs to pay: nothing was checked
};

struct RunSweepOptions {
  std::uint32_t run_cap = 32;  // most edges in one run (>= 1)
  // When runs would average fewer edges than this, the vertex sweep is cheaper: not tried
  // when rings average fewer than 4 times this many edges, undecided when the runs cut turn
  // out that short (spiky rings), or half as long in a set of several rings; 0 always sweeps.
  std::uint32_t min_edges_per_run = 4;
  // Undecided once the box and edge tests exceed this many per edge (keeps the path O(n)
  // beyond its sort; a wide arrangement goes to the vertex sweep, O(n log n)).
  std::uint32_t work_per_edge = 8;
};

// Whether polygons[i] for i in `members` (all of them when `members` is empty) form a valid
// polygon set, settled by the local rules of each ring and the run sweep: O(n) plus the sort
// of the runs, O((n / cap) log n). kUndecided promises that every ring passes its local
// rules (>= 3 vertices, in range, no repeated vertex, no spike, positive area); it is the
// answer whenever edges of two different rings touch without crossing (the winding walk of
// the vertex sweep judges those), and when the input is too wide for the work budget.
RunVerdict sweep_monotone_runs(std::span<const Polygon> polygons,
                               std::span<const std::size_t> members,
                               const RunSweepOptions& options = {});

// Whether one ring passes those local rules: the same pass without the runs, O(n).
bool local_rules_hold(const Ring& ring);

}  // namespace edgeland::detail
