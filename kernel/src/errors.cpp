#include "edgeland/kernel/errors.hpp"

namespace edgeland {
namespace {

const char* operand_name(Operand o) {
  switch (o) {
    case Operand::kSubject: return "subject";
    case Operand::kClip: return "clip";
    case Operand::kRings: return "rings";
    case Operand::kQuery: return "query";
  }
  return "?";  // Not reached by tests: the switch covers every Operand.
}

}  // namespace

InvalidInput::InvalidInput(Operand which, Violation v)
    : Error(std::string("invalid ") + operand_name(which) + ": " + v.describe()),
      operand(which),
      violation(v) {}

CoordinateOutOfRange::CoordinateOutOfRange(Operand which, Violation v)
    : InvalidInput(which, v), polygon(v.polygon), vertex(v.edge), where(v.where) {}

namespace {

Violation out_of_range(std::size_t polygon, std::size_t vertex, Point64 where) {
  Violation v;
  v.rule = Rule::kCoordinateOutOfRange;
  v.polygon = polygon;
  v.edge = vertex;
  v.where = where;
  return v;
}

}  // namespace

CoordinateOutOfRange::CoordinateOutOfRange(Operand which, std::size_t polygon_index,
                                           std::size_t vertex_index, Point64 location)
    : CoordinateOutOfRange(which, out_of_range(polygon_index, vertex_index, location)) {}

void throw_invalid_input(Operand operand, const Violation& violation) {
  if (violation.rule == Rule::kCoordinateOutOfRange) throw CoordinateOutOfRange(operand, violation);
  throw InvalidInput(operand, violation);
}

}  // namespace edgeland
