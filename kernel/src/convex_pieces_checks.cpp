// The checker of convex_pieces() (convex_pieces_checks.hpp).
#include "convex_pieces_checks.hpp"

#include <string>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/convexity.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

bool turns_strictly_left(const Polygon& piece) {
  const std::size_t m = piece.size();
  for (std::size_t i = 0; i < m; ++i) {
    if (orientation(piece[i], piece[(i + 1) % m], piece[(i + 2) % m]) !=
        Orientation::kCounterClockwise)
      return false;
  }
  return is_convex(piece);  // and winds once
}

}  // namespace

void check_convex_pieces(const Polygon& polygon, const std::vector<Polygon>& pieces,
                         std::size_t max_vertices) {
  arith::Checked<Int128> sum = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Polygon& piece = pieces[k];
    if (piece.size() < 3 || piece.size() > max_vertices)
      fail_stage("convex_pieces", "piece " + std::to_string(k) + " has " +
                                      std::to_string(piece.size()) + " vertices");
    if (!turns_strictly_left(piece))
      fail_stage("convex_pieces", "piece " + std::to_string(k) + " is not strictly convex");
    sum = sum + arith::Checked<Int128>(twice_signed_area(piece));
  }
  if (sum.v != twice_signed_area(polygon))
    fail_stage("convex_pieces", "the pieces' areas do not sum to the polygon's");
}

}  // namespace edgeland::detail
