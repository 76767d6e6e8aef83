#pragma once
// Noding (thesis 3.3): every contact between segments, found exactly.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "segment_search.hpp"

namespace edgeland::detail {

struct Contacts {
  // (segment, integer point strictly inside it where it must be split)
  ScratchVector<std::pair<std::uint32_t, Point64>> splits;
  // Pixels of proper crossings at non-integer points (rounded by round_to_grid).
  ScratchVector<Point64> hot;
  // touched[s]: segment s meets another one anywhere except ring neighbours (next[s]) at their
  // one shared endpoint (find_contacts only): an untouched segment shares no point with
  // anything else.
  ScratchVector<std::uint8_t> touched;
  // Pairs of segments that meet other than at a shared endpoint.
  std::size_t intersections = 0;
  // Only when screening (below): noding stopped at a contact that proves an operand invalid;
  // the rest of the contacts are then incomplete.
  bool operand_invalid = false;
  // Pairs of collinear segments sharing a stretch of positive length (counted by classify_pair).
  std::size_t overlaps = 0;
  // Noding stopped when `overlaps` passed its budget (find_contacts); the contacts are then
  // incomplete.
  bool overlap_heavy = false;
  // Noding stopped early: the contacts are incomplete and no stage after it runs.
  bool stopped() const { return operand_invalid || overlap_heavy; }
};

struct NodingOptions {
  // Every ring is strictly simple (validated operands), so two segments of one ring meet only
  // as neighbours at their shared endpoint and such pairs are not tested at all.
  bool simple_rings = false;
  // The operand of each segment, when the operands are not validated yet (the validating
  // clip(), clip/README.md): every pair is tested, and noding stops, setting
  // c.operand_invalid, at the first contact proving an operand invalid: two segments of one
  // ring meeting other than as neighbours at their shared endpoint (not strictly simple), or two
  // of different rings of one operand crossing properly or overlapping in the same direction
  // (their insides overlap). Stopping there keeps an invalid operand with n^2 such contacts from
  // costing n^2 before it is rejected.
  const std::vector<std::uint8_t>* screen_channel = nullptr;
  // Noding stops, setting c.overlap_heavy, once more pairs than this overlap along a stretch (a
  // stack of collinear edges: collinear_merge.hpp).
  std::size_t overlap_budget = std::numeric_limits<std::size_t>::max();
};

// Finds all contacts among `segments` (candidates from search.index), with Contacts::touched.
// O(r log r + candidate pairs) for r runs of the index. When it walks the segments through a
// SegmentGrid (short runs: spiky inputs), the grid is left in search.near for snap rounding's
// point queries.
Contacts find_contacts(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next,
                       SegmentSearch& search, const NodingOptions& options);

enum class Meeting : std::uint8_t {
  kNone,            // disjoint
  kSharedEndpoint,  // only a common endpoint of both
  kOther,           // anything else (recorded in the contacts)
};

// Exact classification of one pair, adding what it finds to `c`.
Meeting classify_pair(const Segment& s, std::uint32_t i, const Segment& t, std::uint32_t j,
                      Contacts& c);

}  // namespace edgeland::detail
