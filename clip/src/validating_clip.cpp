// The validating clip() and its fallback (validating_clip.hpp).
#include "validating_clip.hpp"

#include "clip_near.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "operand_screen.hpp"
#include "pipeline.hpp"

namespace edgeland::detail {

ClipResult validating_clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                           const ClipOptions& options) {
  auto validate_both = [&] {
    require_valid(subject, Operand::kSubject);
    require_valid(clip_set, Operand::kClip);
  };
  // Validated while clipped (Screening); anything the screen or the pipeline doubts is
  // validated in full, so errors are exactly validate()'s, subject first.
  if (!rings_pass_screen(subject) || !rings_pass_screen(clip_set)) {
    validate_both();
    // Not reached by tests: every valid set passes the screen (the least vertex of a valid
    // ring is a strict left turn), so validate_both() has thrown; kept should the screen
    // ever be stricter than validate().
    return clip_of_valid(op, subject, clip_set, options);
  }
  Screening screen{{&subject, &clip_set}};
  ClipResult r = guarded(
      [&] { return clip_near(op, subject, clip_set, false, false, options.checked, &screen); },
      options, op_name(op), [&] { return to_wkt(subject); }, [&] { return to_wkt(clip_set); },
      validate_both);
  if (!screen.suspect) return r;
  validate_both();
  // Not reached by tests: the pipeline finds only invalid operands suspect, and then
  // validate_both() has thrown; kept for a false alarm of the screen.
  return clip_of_valid(op, subject, clip_set, options);
}

}  // namespace edgeland::detail
