#include "edgeland/kernel/errors.hpp"

namespace edgeland {

CoordinateOutOfRange::CoordinateOutOfRange(std::size_t polygon_index, std::size_t vertex_index,
                                           Point64 location)
    : Error("coordinate out of range at polygon " + std::to_string(polygon_index) + " vertex " +
            std::to_string(vertex_index) + " (" + std::to_string(location.x) + " " +
            std::to_string(location.y) + "): |c| must be <= " + std::to_string(kCoordBound)),
      polygon(polygon_index),
      vertex(vertex_index),
      where(location) {}

}  // namespace edgeland
