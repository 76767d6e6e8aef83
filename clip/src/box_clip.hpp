#pragma once
// clip_to_box(): a set cut to an axis-aligned box through the full pipeline, so the result is
// closed under repetition exactly like clip()'s.
#include "edgeland/clip/types.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// The box is the clip operand: a corner beyond the bound is CoordinateOutOfRange, then
// min > max is InvalidBox.
void require_valid_box(const Box64& box);

// set ∩ box for a valid set and a valid box; empty for a box of zero width or height.
// collinear_free: no ring of the set has collinear consecutive vertices (the box has none).
ClipResult clip_valid_to_box(const PolygonSet& set, const Box64& box, const ClipOptions& options,
                             bool collinear_free);

}  // namespace edgeland::detail
