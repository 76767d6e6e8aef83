#pragma once
// The locality filter of clip(): only the subject polygons that can interact with the clip
// operand go through the pipeline; the others are kept (or dropped by an intersection) as they
// are. Both ways in, the validating clip() (validating_clip.hpp) and the ValidSet overload,
// clip through here.
#include "edgeland/clip/types.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "pipeline.hpp"

namespace edgeland::detail {

// subject OP clip_set, the pipeline run on the subject polygons near the clip operand.
// A subject polygon is left out when its box stays clear of the clip operand's box and of every
// segment snap rounding moved (one unit of margin: a snapped segment stays within half a unit of
// where it was). Left-out polygons are unaffected by the operation: kept as they are, or dropped
// by an intersection. If rounding moved a segment near a left-out polygon, that polygon is
// brought in and the operation re-run; the included set only grows, so this terminates.
// subject_canonical: the subject is in canonical form (an earlier result), so left-out polygons
// are copied as they are and merged into the sorted result.
// collinear_free: no ring of either operand has collinear consecutive vertices.
// check_stages: run the stage checkers (checked mode).
// screening: operands not validated yet (Screening); when it finds one suspect, the result is
// empty and screening->suspect is set.
ClipResult clip_near(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                     bool subject_canonical, bool collinear_free, bool check_stages,
                     Screening* screening = nullptr);

// clip_near() of operands known to be valid, guarded (pipeline.hpp: an internal failure or, in
// checked mode, an invalid output is an InternalError with the inputs).
ClipResult clip_of_valid(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                         const ClipOptions& options, bool subject_canonical = false,
                         bool collinear_free = false);

}  // namespace edgeland::detail
