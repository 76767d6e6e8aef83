#pragma once
// Brute-force references for the landscape's queries and the exact history of its edits, written
// from the definitions in landscape.hpp and sharing no code with spatial/:
//   * the material at a point by the half-open rule, p + eps (1, eps), evaluated at an actual
//     tiny rational eps with GMP rationals over every polygon of the landscape;
//   * the material profile along a segment: every parameter where the segment's line meets a
//     vertex or crosses an edge line, sorted; the material on each open interval between two of
//     them (at the midpoint, moved by the same eps); the changes between intervals;
//   * the material a point has after a sequence of edits applied exactly, for points that lie
//     clearly inside or outside every shape.
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::test {

// One edit as the tests apply it.
struct LandscapeEdit {
  enum class Kind { kCarve, kFill, kFillEmpty, kReplace } kind = Kind::kCarve;
  PolygonSet shape;
  Material a = 0, b = 0;  // fill / fill_empty: a; replace: a -> b
};
std::string describe(const LandscapeEdit& e);
ChangeSet apply(Landscape& l, const LandscapeEdit& e);
// The material a point gets from one edit, given the one it had and whether it is inside the
// shape (and the world).
Material apply_pointwise(const LandscapeEdit& e, Material before, bool inside_shape);

// Every polygon of the landscape with its material (a flat copy).
struct FlatPolygon {
  Material material;
  Polygon ring;
  Box64 box;
};
std::vector<FlatPolygon> flatten(const Landscape& l);

// The material at the rational point q moved by (eps, eps^2), eps = 2^-100 (coordinates of the
// tests are below 2^20, so no boundary lies between q and the moved point unless q is on it).
Material material_brute(const std::vector<FlatPolygon>& polys, const QPoint& q);

struct BruteCrossing {
  Rational t;
  Material before, after;
};
// The changes of material along from -> to (moved by eps (1, eps)), at t in [0, 1], with the
// material just behind `from` as the first `before`; a change where the segment enters or
// leaves the world box is none (the world's border is no surface for rays).
std::vector<BruteCrossing> profile_brute(const std::vector<FlatPolygon>& polys, const Box64& world,
                                         Point64 from, Point64 to);

}  // namespace edgeland::test
