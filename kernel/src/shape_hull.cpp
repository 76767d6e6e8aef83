// convex_hull (shape_hull.hpp): Andrew's monotone chain (A. M. Andrew, "Another efficient
// algorithm for convex hulls in two dimensions", 1979): sort, then one pass for the lower chain
// and one for the upper, each keeping only strict left turns.
#include "shape_hull.hpp"

#include <algorithm>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland::detail {
namespace {

using W = arith::Checked<Int128>;

// Whether a -> b -> c turns strictly left (coordinates within kShapeCoordBound: proofs/,
// shape_hull_orient_int128).
bool left_turn(Point64 a, Point64 b, Point64 c) {
  return formulas::orient<W>(a.x, a.y, b.x, b.y, c.x, c.y) > W(0);
}

// Appends p to the chain after dropping every last point that would not make a strict left
// turn; the chain before `floor` is never touched.
void push_turning_left(Polygon& chain, std::size_t floor, Point64 p) {
  while (chain.size() >= floor + 2 && !left_turn(chain[chain.size() - 2], chain.back(), p))
    chain.pop_back();
  chain.push_back(p);
}

}  // namespace

Polygon convex_hull(std::vector<Point64> points) {
  std::sort(points.begin(), points.end(),
            [](Point64 a, Point64 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  Polygon hull;
  for (const Point64 p : points) push_turning_left(hull, 0, p);  // lower chain, west to east
  const std::size_t upper = hull.size() - 1;  // the east end starts the upper chain
  for (auto it = points.rbegin() + 1; it != points.rend(); ++it)
    push_turning_left(hull, upper, *it);
  hull.pop_back();  // the west end again
  return hull;
}

}  // namespace edgeland::detail
