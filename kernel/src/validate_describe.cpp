// Names and one-line descriptions of violations (validate.hpp).
#include <string>

#include "edgeland/kernel/validate.hpp"

namespace edgeland {

const char* rule_name(Rule rule) noexcept {
  switch (rule) {
    case Rule::kTooFewVertices:
      return "too-few-vertices";
    case Rule::kCoordinateOutOfRange:
      return "coordinate-out-of-range";
    case Rule::kRepeatedVertex:
      return "repeated-vertex";
    case Rule::kSelfIntersection:
      return "self-intersection";
    case Rule::kSpike:
      return "spike";
    case Rule::kNotCounterClockwise:
      return "not-counter-clockwise";
    case Rule::kOverlappingInteriors:
      return "overlapping-interiors";
    case Rule::kInvertedBox:
      return "inverted-box";
  }
  return "unknown-rule";  // Not reached by tests: the switch covers every Rule.
}

std::string Violation::describe() const {
  auto num = [](std::size_t i) { return std::to_string(i); };
  const std::string at = " at (" + std::to_string(where.x) + " " + std::to_string(where.y) + ")";
  if (rule == Rule::kInvertedBox) return std::string(rule_name(rule)) + ": min corner" + at;
  std::string text = std::string(rule_name(rule)) + ": polygon " + num(polygon);
  switch (rule) {
    case Rule::kCoordinateOutOfRange:
      if (edge != kNone) text += " vertex " + num(edge);
      break;
    case Rule::kRepeatedVertex:
      if (edge != kNone) text += " edge " + num(edge) + " has zero length";
      break;
    default:
      if (other_polygon != kNone) {
        if (edge != kNone) text += " edge " + num(edge);
        text += " and polygon " + num(other_polygon);
        if (other_edge != kNone) text += " edge " + num(other_edge);
      } else if (edge != kNone && other_edge != kNone) {
        text += " edges " + num(edge) + " and " + num(other_edge);
      } else if (edge != kNone) {
        text += " edge " + num(edge);
      }
      break;
  }
  return text + at;
}

}  // namespace edgeland
