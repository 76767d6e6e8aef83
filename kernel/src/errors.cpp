#include "edgeland/kernel/errors.hpp"

#include "edgeland/kernel/point_text.hpp"

namespace edgeland {
namespace {

const char* operand_name(Operand o) {
  switch (o) {
    case Operand::kSubject:
      return "subject";
    case Operand::kClip:
      return "clip";
    case Operand::kRings:
      return "rings";
    case Operand::kQuery:
      return "query";
    case Operand::kPolygon:
      return "polygon";
    case Operand::kShape:
      return "shape";
  }
  return "?";  // Not reached by tests: the switch covers every Operand.
}

std::string text(Point64 p) { return detail::point_text(p); }

Violation out_of_range(std::size_t polygon, std::size_t vertex, Point64 where) {
  Violation v;
  v.rule = Rule::kCoordinateOutOfRange;
  v.polygon = polygon;
  v.edge = vertex;
  v.where = where;
  return v;
}

// validate()'s description with the ring named after the polygon when it is not 0.
std::string out_of_range_description(const Violation& v, std::size_t ring) {
  if (ring == 0) return v.describe();
  std::string d = std::string(rule_name(v.rule)) + ": polygon " + std::to_string(v.polygon) +
                  " ring " + std::to_string(ring);
  if (v.edge != kNone) d += " vertex " + std::to_string(v.edge);
  return d + " at " + text(v.where);
}

Violation inverted(const Box64& box) {
  Violation v;
  v.rule = Rule::kInvertedBox;
  v.where = box.min;
  return v;
}

// "inverted-box: min (5 0) exceeds max (0 5) in x", naming each axis where min > max.
std::string inverted_description(const Box64& b) {
  std::string axes;
  if (b.min.x > b.max.x) axes = " in x";
  if (b.min.y > b.max.y) axes += axes.empty() ? " in y" : " and y";
  return std::string(rule_name(Rule::kInvertedBox)) + ": min " + text(b.min) + " exceeds max " +
         text(b.max) + axes;
}

}  // namespace

InvalidInput::InvalidInput(Operand which, Violation v) : InvalidInput(which, v, v.describe()) {}

InvalidInput::InvalidInput(Operand which, Violation v, const std::string& description)
    : Error(std::string("invalid ") + operand_name(which) + ": " + description),
      operand(which),
      violation(v) {}

CoordinateOutOfRange::CoordinateOutOfRange(Operand which, Violation v)
    : InvalidInput(which, v), polygon(v.polygon), ring(0), vertex(v.edge), where(v.where) {}

CoordinateOutOfRange::CoordinateOutOfRange(Operand which, std::size_t polygon_index,
                                           std::size_t ring_index, std::size_t vertex_index,
                                           Point64 location)
    : InvalidInput(which, out_of_range(polygon_index, vertex_index, location),
                   out_of_range_description(out_of_range(polygon_index, vertex_index, location),
                                            ring_index)),
      polygon(polygon_index),
      ring(ring_index),
      vertex(vertex_index),
      where(location) {}

CoordinateOutOfRange::CoordinateOutOfRange(Operand which, std::size_t vertex_index,
                                           Point64 location, const std::string& description)
    : InvalidInput(which, out_of_range(0, vertex_index, location), description),
      polygon(0),
      ring(0),
      vertex(vertex_index),
      where(location) {}

CoordinateOutOfRange CoordinateOutOfRange::query_argument(std::size_t index, const char* name,
                                                          Point64 location) {
  return argument(Operand::kQuery, index, name, location);
}

CoordinateOutOfRange CoordinateOutOfRange::argument(Operand which, std::size_t index,
                                                    const char* name, Point64 location) {
  const std::string rule = rule_name(Rule::kCoordinateOutOfRange);
  return CoordinateOutOfRange(which, index, location, rule + ": " + name + " at " + text(location));
}

InvalidBox::InvalidBox(Operand which, const Box64& b)
    : InvalidInput(which, inverted(b), inverted_description(b)), box(b) {}

TooManyVertices::TooManyVertices(std::size_t max, std::size_t count)
    : Error("too many vertices: " + std::to_string(count) + " given, at most " +
            std::to_string(max) + " accepted"),
      maximum(max),
      requested(count) {}

InvalidArgument::InvalidArgument(const char* name, std::size_t given, std::size_t least)
    : Error(std::string("invalid argument: ") + name + " = " + std::to_string(given) +
            ", must be at least " + std::to_string(least)),
      argument(name),
      value(given),
      minimum(least) {}

ArgumentOutOfRange::ArgumentOutOfRange(const char* name, std::int64_t given, std::int64_t least,
                                       std::int64_t most)
    : Error(std::string("argument out of range: ") + name + " = " + std::to_string(given) +
            ", must be in [" + std::to_string(least) + ", " + std::to_string(most) + "]"),
      argument(name),
      value(given),
      minimum(least),
      maximum(most) {}

NonPositiveArea::NonPositiveArea(Int128 total)
    : Error("no centroid: the total twice-area " + to_string(total) + " is not positive"),
      twice_area(total) {}

void throw_invalid_input(Operand operand, const Violation& violation) {
  if (violation.rule == Rule::kCoordinateOutOfRange) throw CoordinateOutOfRange(operand, violation);
  throw InvalidInput(operand, violation);
}

}  // namespace edgeland
