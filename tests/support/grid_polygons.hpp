#pragma once
// Bounded-exhaustive inputs for the polygon algorithms' tests: every strictly simple
// counter-clockwise polygon with vertices on a small grid.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"
#include "validate_generators.hpp"

namespace edgeland::testing {

// Every strictly simple counter-clockwise polygon on the grid [0, w) x [0, h) with at most
// max_vertices vertices, once each (its rotation starting at its first grid point): vertex
// sequences grown edge by edge, a path that already touches itself cut off, each closed ring
// kept when validate() accepts it.
class GridPolygons {
 public:
  GridPolygons(std::int64_t w, std::int64_t h, std::size_t max_vertices)
      : points_(grid_points(w, h)), max_(max_vertices) {}

  template <class F>
  void for_each(F&& f) {
    for (std::size_t first = 0; first < points_.size(); ++first) {
      path_ = {points_[first]};
      grow(first, f);
    }
  }

 private:
  // The new edge from the path's end to q meets the path only at the path's end.
  bool extends(Point64 q) const {
    const Segment e{path_.back(), q};
    for (std::size_t k = 0; k + 1 < path_.size(); ++k) {
      const SegmentIntersection x = intersect(e, {path_[k], path_[k + 1]});
      if (x.relation == SegmentRelation::kDisjoint) continue;
      if (k + 2 == path_.size() && x.relation == SegmentRelation::kTouching) continue;
      return false;
    }
    return std::find(path_.begin(), path_.end(), q) == path_.end();
  }

  template <class F>
  void grow(std::size_t first, F& f) {
    if (path_.size() >= 3 && validate(path_, 1).ok()) f(path_);
    if (path_.size() == max_) return;
    for (std::size_t k = first + 1; k < points_.size(); ++k) {
      if (!extends(points_[k])) continue;
      path_.push_back(points_[k]);
      grow(first, f);
      path_.pop_back();
    }
  }

  std::vector<Point64> points_;
  std::size_t max_;
  Polygon path_;
};

}  // namespace edgeland::testing
