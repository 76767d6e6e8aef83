#pragma once
// Canonical form of a result: no collinear consecutive vertices, each ring starting at its
// smallest vertex, rings sorted. Makes equal results byte-identical.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// `ring` must be simple with nonzero area. O(n).
Ring canonical_ring(Ring ring);

// The canonical ring of the simple closed polyline `points`, built in one pass: it starts at
// points[least], its smallest point, and drops collinear points. Only points with check[i] != 0
// (every point when check is null) are tested, and any point whose neighbour was dropped: the
// caller vouches that the others are not collinear with their neighbours (points inside a
// stretch of a canonical input ring).
// turn: the orientation at the smallest point, which is the ring's orientation (+1
// counter-clockwise, -1 clockwise; the smallest vertex of a simple polygon is convex), or 0 when
// the ring is degenerate (then the ring returned may be anything). O(n).
Ring canonical_ring_from(const std::vector<Point64>& points, const std::uint8_t* check,
                         std::size_t least, int& turn);
// The same, into `out` (cleared first): scratch storage reused.
void canonical_ring_into(const std::vector<Point64>& points, const std::uint8_t* check,
                         std::size_t least, int& turn, Ring& out);

// Whether no ring of `set` has three consecutive collinear vertices (cyclically). O(n).
bool collinear_free(const PolygonSet& set);

// Canonical order: rings sorted (each already canonical). O(p log p). labels (optional, one per
// ring) are permuted along.
void sort_canonical(PolygonSet& set, std::vector<std::int64_t>* labels = nullptr);

// Drops every point of the ring that is collinear with its neighbours, except points listed in
// `keep` (sorted): for a region's rings before hole splitting, where points two rings touch at
// must stay. The result starts at its smallest point. `ring` must be simple with nonzero area.
// O(n log k).
void drop_collinear_except(Ring& ring, const std::vector<Point64>& keep);

}  // namespace edgeland::detail
