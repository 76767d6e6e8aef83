#pragma once
// The clipper's own errors. The input errors (InvalidInput, CoordinateOutOfRange, InvalidBox)
// are the kernel's (kernel/errors.hpp): every operation validates its operands the same way.
#include <cstddef>
#include <cstdint>
#include <string>

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"

namespace edgeland {

// A result failed the checkers in checked mode: a bug in edgeland. Carries the inputs.
class EDGELAND_EXPORT InternalError : public Error {
 public:
  InternalError(const std::string& what, std::string subject_wkt, std::string clip_wkt);
  std::string subject_wkt;
  std::string clip_wkt;
};

// The arguments of an overlay (relabel.hpp) do not fit together (the geometry itself is
// checked by ValidSet).
class EDGELAND_EXPORT InvalidOverlay : public Error {
 public:
  enum class Reason : std::uint8_t {
    kLabelCount,      // labels.size() differs from the number of polygons
    kZeroLabel,       // a member is labeled 0
    kOutsideWindow,   // a member of `regions` is not inside the window
    kBadWindow,       // a window is not a box with positive area within the coordinate bound
    kWindowsOverlap,  // two windows share interior points
    kTooManySteps,    // a batch of more than kMaxBatchSteps steps (relabel_batch)
    kNoShape,         // a batch step without a shape
  };
  InvalidOverlay(Reason reason, std::size_t index);
  Reason reason;
  std::size_t index;  // the member or window concerned
};

}  // namespace edgeland
