// Half-edge cycles of convex_pieces()'s pieces (piece_mesh.hpp).
#include "piece_mesh.hpp"

#include <algorithm>

#include "edgeland/kernel/assert.hpp"

namespace edgeland::detail {
namespace {

// A diagonal half-edge keyed by its unordered pair of vertices, for pairing twins.
struct Keyed {
  std::uint64_t key;
  std::uint32_t half_edge;
};

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

bool polygon_edge(std::uint32_t a, std::uint32_t b, std::size_t n) {
  return b == (a + 1) % n || a == (b + 1) % n;
}

}  // namespace

PieceMesh::PieceMesh(const Polygon& polygon, const std::vector<Triangle>& triangles)
    : polygon_(polygon) {
  const auto count = static_cast<std::uint32_t>(3 * triangles.size());
  origin_.resize(count);
  next_.resize(count);
  prev_.resize(count);
  twin_.assign(count, kNoTwin);
  alive_.assign(count, 1);
  parent_.resize(triangles.size());
  corners_.assign(triangles.size(), 3);
  ScratchVector<Keyed> diagonals;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const std::uint32_t c[3] = {triangles[t].a, triangles[t].b, triangles[t].c};
    parent_[t] = t;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t h = 3 * t + k;
      origin_[h] = c[k];
      next_[h] = 3 * t + (k + 1) % 3;
      prev_[h] = 3 * t + (k + 2) % 3;
      if (!polygon_edge(c[k], c[(k + 1) % 3], polygon.size()))
        diagonals.push_back({pair_key(c[k], c[(k + 1) % 3]), h});
    }
  }
  std::sort(diagonals.begin(), diagonals.end(),
            [](const Keyed& x, const Keyed& y) { return x.key < y.key; });
  for (std::size_t i = 0; i + 1 < diagonals.size(); i += 2) {
    EDGELAND_ASSERT(diagonals[i].key == diagonals[i + 1].key, "convex_pieces",
                    "a diagonal without its twin");
    twin_[diagonals[i].half_edge] = diagonals[i + 1].half_edge;
    twin_[diagonals[i + 1].half_edge] = diagonals[i].half_edge;
  }
}

std::uint32_t PieceMesh::root(std::uint32_t triangle) {
  while (parent_[triangle] != triangle) {
    parent_[triangle] = parent_[parent_[triangle]];  // path halving
    triangle = parent_[triangle];
  }
  return triangle;
}

void PieceMesh::merge_across(std::uint32_t h, std::uint32_t corners) {
  const std::uint32_t t = twin_[h];
  const std::uint32_t p = root(h / 3), q = root(t / 3);
  EDGELAND_ASSERT(p != q, "convex_pieces", "a diagonal inside one piece");
  // ... prev(h) -> next(t) ... and ... prev(t) -> next(h) ...
  next_[prev_[h]] = next_[t];
  prev_[next_[t]] = prev_[h];
  next_[prev_[t]] = next_[h];
  prev_[next_[h]] = prev_[t];
  alive_[h] = alive_[t] = 0;
  parent_[q] = p;
  corners_[p] = corners;
}

}  // namespace edgeland::detail
