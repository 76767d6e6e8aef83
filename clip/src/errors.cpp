// The clipper's own errors (errors.hpp).
#include "edgeland/clip/errors.hpp"

#include <utility>

namespace edgeland {
namespace {

const char* reason_text(InvalidOverlay::Reason r) {
  switch (r) {
    case InvalidOverlay::Reason::kLabelCount:
      return "the number of labels differs from the number of polygons";
    case InvalidOverlay::Reason::kZeroLabel:
      return "a polygon is labeled 0";
    case InvalidOverlay::Reason::kOutsideWindow:
      return "a polygon is not inside the window";
    case InvalidOverlay::Reason::kBadWindow:
      return "a window is not a box of positive area within the coordinate bound";
    case InvalidOverlay::Reason::kWindowsOverlap:
      return "two windows overlap";
    case InvalidOverlay::Reason::kTooManySteps:
      return "more batch steps than one overlay takes";
    case InvalidOverlay::Reason::kNoShape:
      return "a batch step has no shape";
  }
  return "?";  // Not reached by tests: the switch covers every Reason.
}

}  // namespace

InternalError::InternalError(const std::string& what, std::string subject, std::string clip)
    : Error("edgeland internal error (please report with the inputs): " + what),
      subject_wkt(std::move(subject)),
      clip_wkt(std::move(clip)) {}

InvalidOverlay::InvalidOverlay(Reason r, std::size_t i)
    : Error(std::string("invalid overlay: ") + reason_text(r) + " (index " + std::to_string(i) +
            ")"),
      reason(r),
      index(i) {}

}  // namespace edgeland
