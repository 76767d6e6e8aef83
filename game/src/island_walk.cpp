#include "island_walk.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "edgeland/kernel/area.hpp"

namespace edgeland::game_detail {
namespace {

// The segment of side `s` of `box` from lo to hi along it, as a (flat) box.
Box64 side_box(const Box64& box, Side s, std::int64_t lo, std::int64_t hi) {
  return segment_box(point_on(box, s, lo), point_on(box, s, hi));
}

struct Visit {
  const CellRecord* cell;
  std::uint32_t group;
  friend bool operator==(const Visit&, const Visit&) = default;
};

class Walk {
 public:
  Walk(const Landscape& world, const CellStore& store) : world_(world), store_(store) {}

  void visit(const CellRecord& cell, std::uint32_t group) {
    const Visit v{&cell, group};
    if (!known_.insert({v.cell, v.group}).second) return;
    seen_.push_back(v);
    queue_.push_back(v);
  }

  void run() {
    while (!queue_.empty()) {
      const Visit v = queue_.back();
      queue_.pop_back();
      for (Side side : kSides)
        for (const Port& p : v.cell->scan.ports[static_cast<std::size_t>(side)])
          if (p.group == v.group) cross(v.cell->scan.box, side, p);
    }
  }

  std::vector<WalkedPolygon> polygons() const {
    std::vector<WalkedPolygon> out;
    for (const Visit& v : seen_) {
      const CellScan& s = v.cell->scan;
      for (std::size_t i = 0; i < s.group_of.size(); ++i)
        if (s.group_of[i] == v.group)
          out.push_back({s.ids()[i], s.materials[i], &s.contents->polygons()[i], s.box});
    }
    std::sort(out.begin(), out.end(),
              [](const WalkedPolygon& l, const WalkedPolygon& r) { return l.id < r.id; });
    return out;
  }

 private:
  // The neighbours' groups whose ports overlap port p on side `side` of `cell`.
  void cross(const Box64& cell, Side side, const Port& p) {
    world_.cells_in(side_box(cell, side, p.lo, p.hi), [&](const CellView& c) {
      if (!across(cell, side, c.box)) return true;
      const CellRecord& n = store_.at(c.box);
      for (const Port& q : n.scan.ports[static_cast<std::size_t>(opposite(side))])
        if (std::min(p.hi, q.hi) > std::max(p.lo, q.lo)) visit(n, q.group);
      return true;
    });
  }

  const Landscape& world_;
  const CellStore& store_;
  std::set<std::pair<const CellRecord*, std::uint32_t>> known_;
  std::vector<Visit> seen_;  // in the order found
  std::vector<Visit> queue_;
};

}  // namespace

std::vector<WalkedPolygon> walk_piece(const Landscape& world, const CellStore& store,
                                      PolygonId start, const Box64& cell) {
  Walk walk(world, store);
  const CellRecord& record = store.at(cell);
  const std::span<const PolygonId> ids = record.scan.ids();
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] == start && record.scan.group_of[i] != kNotSolid)
      walk.visit(record, record.scan.group_of[i]);
  walk.run();
  return walk.polygons();
}

Island island_of(const Landscape& world, const CellStore& store, const ClosedIsland& closed) {
  Island out;
  for (const WalkedPolygon& p :
       walk_piece(world, store, closed.representative, closed.representative_cell)) {
    out.pieces.push_back({p.id, p.material, *p.ring, p.cell});
    const Box64 b = *bounding_box(*p.ring);
    if (out.pieces.size() == 1)
      out.bounds = b;
    else
      out.bounds.expand(b);
    out.twice_area += twice_signed_area(*p.ring);
  }
  return out;
}

std::vector<Island> islands_of(const Landscape& world, const CellStore& store,
                               std::span<const ClosedIsland> closed) {
  std::vector<Island> out;
  for (const ClosedIsland& c : closed) out.push_back(island_of(world, store, c));
  std::sort(out.begin(), out.end(), [](const Island& l, const Island& r) {
    return l.pieces.front().id < r.pieces.front().id;
  });
  return out;
}

}  // namespace edgeland::game_detail
