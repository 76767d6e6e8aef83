#pragma once
// A cell's pieces of solid (game/README.md, "Debris islands"): its solid polygons grouped by
// contact (a shared boundary of positive length inside the cell, solid_boundary.hpp), each group
// with its ports on the cell's sides and whether it is anchored (an anchored material, or a port
// on the world border).
#include <array>
#include <cstdint>
#include <vector>

#include "solid_boundary.hpp"

namespace edgeland::game_detail {

inline constexpr std::uint32_t kNotSolid = static_cast<std::uint32_t>(-1);

// A port as an interval of the side: lo < hi along it (x on the bottom and top, y on the sides).
struct Port {
  std::int64_t lo = 0, hi = 0;
  std::uint32_t group = 0;  // the piece of solid it belongs to (a class of the summary)
};

struct CellSolids {
  CellPolygons polygons;
  SolidBoundary boundary;
  std::vector<std::uint32_t> group_of;  // per polygon: its group, or kNotSolid
  std::uint32_t groups = 0;
  std::vector<bool> anchored;  // per group
  // Ports per side not on the world border, ascending along the side.
  std::array<std::vector<Port>, 4> ports;
};

CellSolids cell_solids(const Landscape& world, const Box64& cell,
                       const PhysicsMaterials& materials);

// A union-find over 0..n-1 (path halving, union by index: deterministic).
class UnionFind {
 public:
  explicit UnionFind(std::size_t n = 0);
  std::uint32_t find(std::uint32_t x);
  void unite(std::uint32_t a, std::uint32_t b);
  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace edgeland::game_detail
