#pragma once
// The small overlay (clip/README.md, "The small overlay"): noding and snap rounding for an edge
// list of a few dozen segments (a landscape cell's overlay: at most edge_cap region edges and a
// shape reaching them with tens), with no search structure set up. Rings are compared by their
// boxes before their segments, pairs by their boxes before the exact test, hot pixels against
// every segment; the working arrays are one per-thread workspace kept between calls, so the
// steady state allocates nothing here. The fragments handed on are snap_round()'s exactly: the
// same hot pixels, the same routes, the same cuts (the README gives the argument).
#include <cstddef>

#include "input_edges.hpp"
#include "noding.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {

// Edge lists up to this many segments take the small noding and snap rounding.
inline constexpr std::size_t kSmallOverlayUpTo = 256;

// Noding of validated rings (simple_rings): every contact between segments of different rings,
// found ring pair by ring pair; pairs within a ring cannot meet but as neighbours at their
// shared end. The result equals find_contacts()' (the contacts in another order, which no later
// stage depends on).
Contacts find_contacts_small(const EdgeList& edges);

// Snap rounding of find_contacts_small()'s contacts (consumed): snap_round()'s fragments,
// touched flags (or more of them: a segment found meeting another only at a shared end is
// marked too, which only keeps it out of a chain), moved boxes and hot pixel count. Returns false,
// leaving `out` unspecified, when the re-check finds a crossing the stable closure left (never
// seen in testing); the caller then runs the general snap_round().
bool snap_round_small(const EdgeList& edges, Contacts& contacts, Snapped& out);

}  // namespace edgeland::detail
