// Stage 3 of triangulate(): de Berg et al., Computational Geometry, ch. 3.3.
//
// The face's vertices are met in sweep order, each knowing its chain (left: from the first
// vertex counter-clockwise to the last, right: the other way). A stack holds the vertices met
// that may still need diagonals; all but the bottom one lie on one chain, and the chain turns
// away from the interior or runs straight at every vertex strictly inside the stack (reflex or
// straight). Only strictly convex corners are cut off, so a triangle never has three collinear
// corners; the fans toward the other chain cannot be flat either (kernel/README.md).
#include "monotone_triangulation.hpp"

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "sweep_order.hpp"

namespace edgeland::detail {
namespace {

struct ChainVertex {
  std::uint32_t index = 0;  // into the polygon
  bool left = false;        // on the left chain (the interior east of it)
};

// The face's vertices in sweep order, each with its chain; the first and last on both chains
// (marked left and right respectively, which no step depends on). O(m): two sorted chains.
ScratchVector<ChainVertex> merge_chains(const Polygon& p, std::span<const std::uint32_t> face) {
  const std::size_t m = face.size();
  std::size_t top = 0, bottom = 0;
  for (std::size_t k = 1; k < m; ++k) {
    if (sweeps_before(p[face[k]], p[face[top]])) top = k;
    if (sweeps_before(p[face[bottom]], p[face[k]])) bottom = k;
  }
  ScratchVector<ChainVertex> order;
  order.reserve(m);
  order.push_back({face[top], true});
  std::size_t l = (top + 1) % m, r = (top + m - 1) % m;  // next down each chain
  while (l != bottom || r != bottom) {
    const bool take_left = r == bottom || (l != bottom && sweeps_before(p[face[l]], p[face[r]]));
    if (take_left) {
      order.push_back({face[l], true});
      l = (l + 1) % m;
    } else {
      order.push_back({face[r], false});
      r = (r + m - 1) % m;
    }
  }
  order.push_back({face[bottom], false});
  return order;
}

class StackTriangulator {
 public:
  StackTriangulator(const Polygon& p, std::vector<Triangle>& out) : p_(p), out_(out) {}

  void run(const std::vector<ChainVertex>& order) {
    restart(order[0], order[1]);
    for (std::size_t j = 2; j + 1 < order.size(); ++j) {
      if (order[j].left != stack_.back().left) {
        fan_to(order[j]);
        restart(order[j - 1], order[j]);
      } else {
        cut_convex_corners(order[j]);
      }
    }
    fan_to(order.back());
  }

 private:
  // u sees every stacked vertex: triangles from u to each consecutive stacked pair.
  void fan_to(ChainVertex u) {
    const bool stack_left = stack_.back().left;
    for (std::size_t k = 0; k + 1 < stack_.size(); ++k) {
      const std::uint32_t upper = stack_[k].index, lower = stack_[k + 1].index;
      emit(stack_left ? Triangle{u.index, upper, lower} : Triangle{u.index, lower, upper});
    }
  }

  // u on the stack's chain: cut off stacked corners while they are strictly convex.
  void cut_convex_corners(ChainVertex u) {
    ChainVertex last = stack_.back();
    stack_.pop_back();
    while (!stack_.empty() && strictly_convex(stack_.back(), last, u)) {
      const std::uint32_t upper = stack_.back().index;
      emit(u.left ? Triangle{upper, last.index, u.index} : Triangle{u.index, last.index, upper});
      last = stack_.back();
      stack_.pop_back();
    }
    stack_.push_back(last);
    stack_.push_back(u);
  }

  // Whether the chain upper -> corner -> lower turns toward the interior (left chain: a left
  // turn going down; right chain: a right turn), strictly.
  bool strictly_convex(ChainVertex upper, ChainVertex corner, ChainVertex lower) const {
    const Orientation o = orientation(p_[upper.index], p_[corner.index], p_[lower.index]);
    return o == (lower.left ? Orientation::kCounterClockwise : Orientation::kClockwise);
  }

  void emit(Triangle t) {
    EDGELAND_ASSERT(orientation(p_[t.a], p_[t.b], p_[t.c]) == Orientation::kCounterClockwise,
                    "triangulate", "a triangle is not counter-clockwise with positive area");
    out_.push_back(t);
  }

  void restart(const ChainVertex& a, const ChainVertex& b) {
    stack_.clear();
    stack_.push_back(a);
    stack_.push_back(b);
  }

  const Polygon& p_;
  std::vector<Triangle>& out_;
  ScratchVector<ChainVertex> stack_;  // scratch storage: a temporary of every face
};

}  // namespace

void triangulate_monotone(const Polygon& polygon, std::span<const std::uint32_t> face,
                          std::vector<Triangle>& out) {
  StackTriangulator(polygon, out).run(merge_chains(polygon, face));
}

}  // namespace edgeland::detail
