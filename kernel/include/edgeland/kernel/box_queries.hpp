#pragma once
// A segment or a ring against an axis-aligned box, exactly: the parameters of a segment inside
// a closed box (walking a ray through the landscape's cells), whether a segment or a ring's
// interior meets a box's open interior (overlap queries). All tests are comparisons of
// coordinates and orientation signs.
#include <optional>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/fraction.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

// The parameters t in [0, 1] with s.a + t (s.b - s.a) in the closed box, as [t0, t1]
// (t0 <= t1; t0 == t1 when the segment only touches the box). nullopt when they miss. A
// degenerate segment (a == b) is a point: [0, 1] if it is in the box. Fractions have
// denominators |dx|, |dy| or 1. O(1).
struct ParameterRange {
  Fraction t0, t1;
};
EDGELAND_EXPORT std::optional<ParameterRange> clip_parameters(const Segment& s,
                                                              const Box64& box) noexcept;

// Whether the closed segment has a point in the open box (min.x, max.x) x (min.y, max.y):
// separating axes x, y and the segment's normal (a segment touching the box only along its
// boundary or at a corner does not meet it; a box of zero width or height has no interior).
// O(1).
EDGELAND_EXPORT bool segment_meets_open_box(const Segment& s, const Box64& box) noexcept;

// Whether the interiors of the box and of a simple ring (either orientation) share a point: an
// edge meets the open box, or the box lies inside the ring (its corner min, seen by the
// half-open rule, is inside). A box of zero width or height has no interior: false. O(n).
EDGELAND_EXPORT bool interiors_overlap(const Box64& box, const Ring& ring) noexcept;

}  // namespace edgeland
