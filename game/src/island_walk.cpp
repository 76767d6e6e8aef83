#include "island_walk.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace edgeland::game_detail {
namespace {

struct BoxLess {
  bool operator()(const Box64& l, const Box64& r) const {
    return l.min != r.min ? l.min < r.min : l.max < r.max;
  }
};

// The side of a neighbour that faces side `s` of a cell.
Side facing(Side s) { return static_cast<Side>((static_cast<int>(s) + 2) % 4); }

// The segment of side `s` of `box` from lo to hi along it, as a (flat) box.
Box64 side_box(const Box64& box, Side s, std::int64_t lo, std::int64_t hi) {
  const Point64 a = point_on(box, s, lo), b = point_on(box, s, hi);
  return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}

// Whether `other` lies across side s of `box` (its facing side on the same line).
bool across(const Box64& box, Side s, const Box64& other) {
  switch (s) {
    case Side::kBottom:
      return other.max.y == box.min.y;
    case Side::kRight:
      return other.min.x == box.max.x;
    case Side::kTop:
      return other.min.y == box.max.y;
    case Side::kLeft:
      return other.max.x == box.min.x;
  }
  return false;
}

class Walk {
 public:
  Walk(const Landscape& world, const PhysicsMaterials& materials)
      : world_(world), materials_(materials) {}

  void visit(const Box64& cell, std::uint32_t group) {
    if (!seen_.insert({cell, group}).second) return;
    queue_.push_back({cell, group});
  }

  void run() {
    while (!queue_.empty()) {
      const auto [cell, group] = queue_.back();
      queue_.pop_back();
      const CellSolids& s = solids(cell);
      for (Side side : kSides)
        for (const Port& p : s.ports[static_cast<std::size_t>(side)])
          if (p.group == group) cross(cell, side, p);
    }
  }

  const CellSolids& solids(const Box64& cell) {
    auto it = cells_.find(cell);
    if (it == cells_.end()) it = cells_.emplace(cell, cell_solids(world_, cell, materials_)).first;
    return it->second;
  }

  std::vector<WalkedPolygon> polygons() {
    std::vector<WalkedPolygon> out;
    for (const auto& [cell, group] : seen_) {
      const CellSolids& s = solids(cell);
      for (std::size_t i = 0; i < s.group_of.size(); ++i)
        if (s.group_of[i] == group) {
          const CellPolygon& p = s.polygons.own[i];
          out.push_back({p.id, p.material, p.ring, cell});
        }
    }
    std::sort(out.begin(), out.end(),
              [](const WalkedPolygon& l, const WalkedPolygon& r) { return l.id < r.id; });
    return out;
  }

 private:
  // The neighbours' groups whose ports overlap port p on side `side` of `cell`.
  void cross(const Box64& cell, Side side, const Port& p) {
    std::vector<Box64> neighbours;
    world_.cells_in(side_box(cell, side, p.lo, p.hi), [&](const CellView& c) {
      if (across(cell, side, c.box)) neighbours.push_back(c.box);
      return true;
    });
    for (const Box64& n : neighbours)
      for (const Port& q : solids(n).ports[static_cast<std::size_t>(facing(side))])
        if (std::min(p.hi, q.hi) > std::max(p.lo, q.lo)) visit(n, q.group);
  }

  const Landscape& world_;
  const PhysicsMaterials& materials_;
  std::map<Box64, CellSolids, BoxLess> cells_;
  std::set<std::pair<Box64, std::uint32_t>, decltype([](const auto& l, const auto& r) {
             return BoxLess{}(l.first, r.first) || (l.first == r.first && l.second < r.second);
           })>
      seen_;
  std::vector<std::pair<Box64, std::uint32_t>> queue_;
};

}  // namespace

std::vector<WalkedPolygon> walk_piece(const Landscape& world, PolygonId start, const Box64& cell,
                                      const PhysicsMaterials& materials) {
  Walk walk(world, materials);
  const CellSolids& s = walk.solids(cell);
  for (std::size_t i = 0; i < s.polygons.own.size(); ++i)
    if (s.polygons.own[i].id == start && s.group_of[i] != kNotSolid)
      walk.visit(cell, s.group_of[i]);
  walk.run();
  return walk.polygons();
}

}  // namespace edgeland::game_detail
