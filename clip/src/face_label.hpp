#pragma once
// What the result keeps of a face, from the state on its side (labeling.hpp): the operation
// table of thesis 3.5 for clip(), a fill rule for normalize(). A plain value, not a
// std::function: assembly asks twice per edge, and an indirect call each time was a few
// percent of a small operation.
#include <cstdint>
#include <span>

#include "edgeland/clip/types.hpp"
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
  const std::int32_t a = st.by_channel[0], b = st.by_channel[1];
  switch (op) {
    case ClipOp::kUnion:
      return a >= 0 ? family(kSubjectChannel, a) : b >= 0 ? family(kClipChannel, b) : -1;
    case ClipOp::kIntersection:
      return a >= 0 && b >= 0 ? family(kSubjectChannel, a) : -1;
    case ClipOp::kDifference:
      return a >= 0 && b < 0 ? family(kSubjectChannel, a) : -1;
    case ClipOp::kXor:
      return a >= 0 && b < 0   ? family(kSubjectChannel, a)
             : a < 0 && b >= 0 ? family(kClipChannel, b)
                               : -1;
  }
  return -1;  // Not reached by tests: the switch covers every ClipOp.
}

inline bool filled(FillRule rule, std::int32_t winding) {
  switch (rule) {
    case FillRule::kEvenOdd:
      return (winding & 1) != 0;
    case FillRule::kNonZero:
      return winding != 0;
    case FillRule::kPositive:
      return winding > 0;
    case FillRule::kNegative:
      return winding < 0;
  }
  return false;  // Not reached by tests: the switch covers every FillRule.
}

// The new label of a face of a labeled overlay (relabel.hpp): channel 0 names the region
// polygon covering the face (its label from region_labels), channel 1 counts the shape
// polygons and the window around it; inside both when the count reaches inside_count.
// Label 0 (no region) is not in the result.
struct RelabelTable {
  const std::uint32_t* region_labels = nullptr;  // per region polygon
  const std::uint32_t* table = nullptr;          // new label inside, per old label
  std::size_t table_size = 0;                    // labels from here on are kept
  std::int32_t inside_count = 1;
  FaceLabel operator()(const SideState& st) const {
    const std::uint32_t old = st.by_channel[0] >= 0 ? region_labels[st.by_channel[0]] : 0;
    const std::uint32_t now =
        st.by_channel[1] >= inside_count && old < table_size ? table[old] : old;
    return now == 0 ? -1 : static_cast<FaceLabel>(now);
  }
};

// The new label of a face of a batch overlay (relabel.hpp, relabel_batch): channel 0 names the
// region polygon covering the face, channel 1 sums, for each step k, its shape's rings around the
// face weighted by 4^k, and the window's (when needed) by 4^steps: two bits per shape, each 0 or
// 1 (a valid set's rings wind once round its inside; the second bit only keeps a count a
// rounding might double from spilling into the next shape's). Inside the window, the region's
// label is passed through the table of every step whose shape holds the face, in order.
struct BatchTable {
  const std::uint32_t* region_labels = nullptr;            // per region polygon
  const std::span<const std::uint32_t>* tables = nullptr;  // per step
  std::uint32_t steps = 0;
  bool window_ring = false;  // the window's ring is in the arrangement (weight 4^steps)
  FaceLabel operator()(const SideState& st) const {
    std::uint32_t label = st.by_channel[0] >= 0 ? region_labels[st.by_channel[0]] : 0;
    const auto inside = static_cast<std::uint32_t>(st.by_channel[1]);
    if (!window_ring || (inside >> (2 * steps)) != 0)
      for (std::uint32_t k = 0; k < steps; ++k)
        if ((inside >> (2 * k)) & 3u) label = label < tables[k].size() ? tables[k][label] : label;
    return label == 0 ? -1 : static_cast<FaceLabel>(label);
  }
};

// The label of a face cut into windows (relabel.hpp, cut_to_windows): the window (channel 1
// owner) in the high half, the region's label in the low half; -1 outside either.
inline FaceLabel window_label(const std::uint32_t* region_labels, const SideState& st) {
  if (st.by_channel[0] < 0 || st.by_channel[1] < 0) return -1;
  return family(st.by_channel[1], 0) | static_cast<FaceLabel>(region_labels[st.by_channel[0]]);
}

class LabelOf {
 public:
  static LabelOf operation(ClipOp op) { return LabelOf(Kind::kOperation, op, FillRule::kEvenOdd); }
  static LabelOf fill(FillRule rule) { return LabelOf(Kind::kFill, ClipOp::kUnion, rule); }
  static LabelOf relabel(const RelabelTable& table) {
    LabelOf l(Kind::kRelabel, ClipOp::kUnion, FillRule::kEvenOdd);
    l.relabel_ = table;
    return l;
  }
  static LabelOf batch(const BatchTable* table) {
    LabelOf l(Kind::kBatch, ClipOp::kUnion, FillRule::kEvenOdd);
    l.batch_ = table;
    return l;
  }
  static LabelOf windows(const std::uint32_t* region_labels) {
    LabelOf l(Kind::kWindows, ClipOp::kUnion, FillRule::kEvenOdd);
    l.relabel_.region_labels = region_labels;
    return l;
  }
  FaceLabel operator()(const SideState& s) const {
    switch (kind_) {
      case Kind::kOperation:
        return op_label(op_, s);
      case Kind::kFill:
        return filled(rule_, s.by_channel[0]) ? 0 : -1;
      case Kind::kRelabel:
        return relabel_(s);
      case Kind::kWindows:
        return window_label(relabel_.region_labels, s);
      case Kind::kBatch:
        return (*batch_)(s);
    }
    return -1;  // Not reached by tests: the switch covers every Kind.
  }

 private:
  enum class Kind : std::uint8_t { kOperation, kFill, kRelabel, kWindows, kBatch };
  LabelOf(Kind kind, ClipOp op, FillRule rule) : kind_(kind), op_(op), rule_(rule) {}
  Kind kind_;
  ClipOp op_;
  FillRule rule_;
  RelabelTable relabel_;
  const BatchTable* batch_ = nullptr;  // the caller's, alive while the pipeline runs
};

}  // namespace edgeland::detail
