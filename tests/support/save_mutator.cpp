#include "save_mutator.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <utility>

#include "edgeland/kernel/splitmix64.hpp"
#include "save_file.hpp"

namespace edgeland::fuzz {
namespace {

// The project's one seeded generator (kernel/: splitmix64.hpp); below(n) draws in [0, n).
using Rng = edgeland::SplitMix64;

// Values where the rules change: 0, 1, the ends of the ranges, off by one.
std::int64_t edge_value(Rng& rng, std::int64_t around) {
  constexpr std::int64_t kBig = std::numeric_limits<std::int64_t>::max();
  // around +- 1 and around * 2 wrap (the mutator may be handed any value a file held).
  const auto wrapped = [](std::uint64_t v) { return static_cast<std::int64_t>(v); };
  const auto u = static_cast<std::uint64_t>(around);
  const std::int64_t values[] = {0,
                                 1,
                                 -1,
                                 wrapped(u - 1),
                                 wrapped(u + 1),
                                 kCoordBound,
                                 -kCoordBound,
                                 kCoordBound + 1,
                                 kBig,
                                 -kBig,
                                 wrapped(u * 2)};
  return values[rng.below(std::size(values))];
}

void mutate_header(SaveFile& f, Rng& rng) {
  switch (rng.below(8)) {
    case 0:
      f.tree = static_cast<std::uint8_t>(rng.below(3));
      break;
    case 1:
      f.edge_cap = static_cast<std::uint32_t>(edge_value(rng, f.edge_cap));
      break;
    case 2:
      f.merge_below = static_cast<std::uint32_t>(rng.below(f.edge_cap + 2));
      break;
    case 3:
      f.min_cell_size = edge_value(rng, f.min_cell_size);
      break;
    case 4:
      f.grid_depth = static_cast<std::int32_t>(rng.below(14)) - 2;
      break;
    case 5:
      f.world[rng.below(4)] = edge_value(rng, f.world[0]);
      break;
    case 6:
      f.next_id = static_cast<std::uint64_t>(edge_value(rng, static_cast<std::int64_t>(f.next_id)));
      break;
    default:
      f.version = static_cast<std::uint32_t>(rng.below(3));
      break;
  }
}

void mutate_nodes(SaveFile& f, Rng& rng) {
  const std::size_t i = rng.below(f.nodes.size() + 1);
  switch (rng.below(4)) {
    case 0:
      if (i < f.nodes.size()) f.nodes.erase(f.nodes.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    case 1:
      if (i < f.nodes.size())
        f.nodes.insert(f.nodes.begin() + static_cast<std::ptrdiff_t>(i), f.nodes[i]);
      break;
    case 2:
      f.nodes.insert(f.nodes.begin() + static_cast<std::ptrdiff_t>(i),
                     SavedNode{rng.below(2) == 0, {}});
      break;
    default:
      if (i < f.nodes.size()) {
        f.nodes[i].inner = !f.nodes[i].inner;
        f.nodes[i].polygons.clear();
      }
      break;
  }
}

// A polygon of some cell, or null when there is none.
SavedPolygon* some_polygon(SaveFile& f, Rng& rng, std::vector<SavedPolygon>** owner = nullptr) {
  std::vector<std::vector<SavedPolygon>*> cells;
  for (SavedNode& n : f.nodes)
    if (!n.polygons.empty()) cells.push_back(&n.polygons);
  if (cells.empty()) return nullptr;
  std::vector<SavedPolygon>& polygons = *cells[rng.below(cells.size())];
  if (owner) *owner = &polygons;
  return &polygons[rng.below(polygons.size())];
}

void mutate_polygon(SaveFile& f, Rng& rng) {
  std::vector<SavedPolygon>* owner = nullptr;
  SavedPolygon* p = some_polygon(f, rng, &owner);
  if (!p) return;
  switch (rng.below(5)) {
    case 0:
      p->id = static_cast<std::uint64_t>(edge_value(rng, static_cast<std::int64_t>(f.next_id)));
      break;
    case 1:
      p->material = static_cast<std::uint8_t>(edge_value(rng, p->material));
      break;
    case 2:
      owner->push_back(*p);
      break;   // the same polygon twice, same id
    case 3: {  // moved into another cell
      SavedPolygon moved = std::move(*p);
      owner->erase(owner->begin() + (p - owner->data()));
      std::vector<SavedPolygon>* other = nullptr;
      if (some_polygon(f, rng, &other)) other->push_back(std::move(moved));
      break;
    }
    default:
      owner->erase(owner->begin() + (p - owner->data()));
      break;
  }
}

void mutate_vertex(SaveFile& f, Rng& rng) {
  SavedPolygon* p = some_polygon(f, rng);
  if (!p || p->ring.empty()) return;
  const std::size_t i = rng.below(p->ring.size());
  Point64& v = p->ring[i];
  switch (rng.below(6)) {
    case 0:
      v.x += rng.below(2) == 0 ? 1 : -1;
      break;
    case 1:
      v.y = edge_value(rng, v.y);
      break;
    case 2:
      p->ring.erase(p->ring.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    case 3:
      p->ring.insert(p->ring.begin() + static_cast<std::ptrdiff_t>(i), v);
      break;
    case 4:
      std::rotate(p->ring.begin(), p->ring.begin() + static_cast<std::ptrdiff_t>(i), p->ring.end());
      break;
    default:
      std::reverse(p->ring.begin(), p->ring.end());
      break;
  }
}

}  // namespace

std::optional<std::string> mutate_save(std::string_view file, std::uint32_t seed) {
  std::optional<SaveFile> f = decode_save(file);
  if (!f) return std::nullopt;
  Rng rng(seed);
  for (std::size_t changes = 1 + rng.below(3); changes > 0; --changes) {
    switch (rng.below(4)) {
      case 0:
        mutate_header(*f, rng);
        break;
      case 1:
        mutate_nodes(*f, rng);
        break;
      case 2:
        mutate_polygon(*f, rng);
        break;
      default:
        mutate_vertex(*f, rng);
        break;
    }
  }
  return encode_save(*f);
}

}  // namespace edgeland::fuzz
