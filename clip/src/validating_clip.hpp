#pragma once
// clip() on PolygonSets: the operands validated while they are clipped, with a fallback to full
// validation (clip/README.md, "Validating while clipping"). Beside the locality filter
// (clip_near.hpp) as GEOS keeps OverlayNGRobust beside OverlayNG: the fast way in, and what
// happens when it has doubts.
#include "edgeland/clip/types.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// subject OP clip_set for operands not validated yet. Throws InvalidInput exactly as validate()
// would report the first violation, the subject's first; InternalError as clip().
ClipResult validating_clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                           const ClipOptions& options);

}  // namespace edgeland::detail
