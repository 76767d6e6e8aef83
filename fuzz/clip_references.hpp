#pragma once
// Exact references for the clipper's targets, written apart from the clipper: which lattice
// points to test, whether a point is safely far from every boundary, what each operation and
// fill rule keeps, and the validity of an output. Defined in clip_references.cpp.
#include <optional>
#include <string>
#include <vector>

#include "clip_decoding.hpp"
#include "decoders.hpp"

namespace edgeland::fuzz {

// Every coordinate within kSmallBound (the point checks below need it).
bool small(const std::vector<Ring>& rings);
// Whether p is farther than 1.5 units from every edge of `rings` (small rings): the output's
// boundary lies within a unit of the exact one, so such a point is classified alike by both.
bool far_from_rings(Point64 p, const std::vector<Ring>& rings);
// Lattice sample points: a 9x9 grid over the rings' box (grown by 3) and points around every
// vertex.
std::vector<Point64> sample_points(const std::vector<Ring>& rings);
// Whether `op` keeps a point in A (in_a) and in B (in_b).
bool op_keeps(ClipOp op, bool in_a, bool in_b);
// Whether `rule` fills a point of winding number w.
bool rule_fills(FillRule rule, int w);
std::string point_text(Point64 p);
// A finding when `out` is not valid or not in canonical form.
std::optional<Finding> invalid_output(const Text& context, const PolygonSet& out,
                                      const Text& log_text);

}  // namespace edgeland::fuzz
