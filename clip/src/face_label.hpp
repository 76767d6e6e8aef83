#pragma once
// What the result keeps of a face, from the state on its side (labeling.hpp): the operation
// table of thesis 3.5 for clip(), a fill rule for normalize(). A plain value, not a
// std::function: assembly asks twice per edge, and an indirect call each time was a few
// percent of a small operation.
#include <cstdint>

#include "edgeland/clip/clip.hpp"
#include "labeling.hpp"

namespace edgeland::detail {

// Which output polygon family a face belongs to, or -1 when not in the result.
using FaceLabel = std::int64_t;

inline FaceLabel family(int channel, std::int32_t polygon) {
  return (static_cast<FaceLabel>(channel) << 32) | static_cast<FaceLabel>(polygon);
}

// The operation table on the polygons covering a face (-1: none). Subject polygons are never
// merged with each other: a face keeps the polygon it came from.
inline FaceLabel op_label(ClipOp op, const SideState& st) {
  const std::int32_t a = st.s[0], b = st.s[1];
  switch (op) {
    case ClipOp::kUnion: return a >= 0 ? family(0, a) : b >= 0 ? family(1, b) : -1;
    case ClipOp::kIntersection: return a >= 0 && b >= 0 ? family(0, a) : -1;
    case ClipOp::kDifference: return a >= 0 && b < 0 ? family(0, a) : -1;
    case ClipOp::kXor:
      return a >= 0 && b < 0 ? family(0, a) : a < 0 && b >= 0 ? family(1, b) : -1;
  }
  return -1;
}

inline bool filled(FillRule rule, std::int32_t winding) {
  switch (rule) {
    case FillRule::kEvenOdd: return (winding & 1) != 0;
    case FillRule::kNonZero: return winding != 0;
    case FillRule::kPositive: return winding > 0;
    case FillRule::kNegative: return winding < 0;
  }
  return false;
}

class LabelOf {
 public:
  static LabelOf operation(ClipOp op) { return LabelOf(false, op, FillRule::kEvenOdd); }
  static LabelOf fill(FillRule rule) { return LabelOf(true, ClipOp::kUnion, rule); }
  FaceLabel operator()(const SideState& s) const {
    if (by_fill_) return filled(rule_, s.s[0]) ? 0 : -1;
    return op_label(op_, s);
  }

 private:
  LabelOf(bool by_fill, ClipOp op, FillRule rule) : by_fill_(by_fill), op_(op), rule_(rule) {}
  bool by_fill_;
  ClipOp op_;
  FillRule rule_;
};

}  // namespace edgeland::detail
