#include "landscape_workloads.hpp"

#include "landscape_shapes.hpp"
#include "unit_draw.hpp"

namespace edgeland::bench {
namespace {

// n edits around `centre` (within 8 units) of radius min_radius .. max_radius, three in four
// carved and one in four filled with material 2.
std::vector<Edit> repeated_at(Point64 centre, double min_radius, double max_radius, std::size_t n) {
  SplitMix64 random(0x5907);
  std::vector<Edit> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 c{centre.x - 8 + static_cast<std::int64_t>(random.next() % 17),
                    centre.y - 8 + static_cast<std::int64_t>(random.next() % 17)};
    const double radius = min_radius + (max_radius - min_radius) * unit_draw(random);
    const std::size_t sides = 16 + random.next() % 33;
    const bool fill = random.next() % 4 == 0;
    out.push_back({ValidSet(PolygonSet{ngon(c, radius, sides)}, Operand::kClip),
                   fill ? EditKind::kFill : EditKind::kCarve, fill ? Material(2) : kEmpty});
  }
  return out;
}

// n mixed edits around `centre` (within 8 units): 7-32-gons of radius 5-60, each carved,
// filled with material 2, or replaced from 2 to 1, a third each in a seeded order.
std::vector<Edit> mixed_at(Point64 centre, std::size_t n) {
  SplitMix64 random(0x4075);
  std::vector<Edit> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 c{centre.x - 8 + static_cast<std::int64_t>(random.next() % 17),
                    centre.y - 8 + static_cast<std::int64_t>(random.next() % 17)};
    const double radius = 5.0 + 55.0 * unit_draw(random);
    const std::size_t sides = 7 + random.next() % 26;
    ValidSet shape(PolygonSet{ngon(c, radius, sides)}, Operand::kClip);
    switch (random.next() % 3) {
      case 0:
        out.push_back({std::move(shape), EditKind::kCarve, kEmpty});
        break;
      case 1:
        out.push_back({std::move(shape), EditKind::kFill, Material(2)});
        break;
      default:
        out.push_back({std::move(shape), EditKind::kReplace, Material(1), Material(2)});
    }
  }
  return out;
}

}  // namespace

const char* workload_name(Workload w) {
  switch (w) {
    case Workload::kCarve:
      return "carve";
    case Workload::kDig:
      return "dig";
    case Workload::kFill:
      return "fill";
    case Workload::kSpot:
      return "spot";
    case Workload::kPit:
      return "pit";
    case Workload::kHotSpot:
      return "hotspot";
  }
  return "?";
}

std::optional<Workload> workload_named(const std::string& name) {
  for (Workload w : kWorkloads)
    if (name == workload_name(w)) return w;
  return std::nullopt;
}

std::vector<Edit> workload_edits(Workload w, std::size_t n) {
  switch (w) {
    case Workload::kCarve:
      return edits_of(EditKind::kCarve, explosions(kCarveSeed, n, kEditWorld), kEmpty);
    case Workload::kDig:
      return edits_of(EditKind::kCarve, digger_strokes(kDigSeed, n, kEditWorld), kEmpty);
    case Workload::kFill:
      return edits_of(EditKind::kFill, explosions(kFillSeed, n, kEditWorld), 2);
    case Workload::kSpot:  // the corner of the quadrants at every level of the tree
      return repeated_at({kEditWorldSide / 2, kEditWorldSide / 2}, 3.0, 200.0, n);
    case Workload::kPit:
      return repeated_at({3001, 2717}, 3.0, 30.0, n);
    case Workload::kHotSpot:
      return mixed_at({kEditWorldSide / 2, kEditWorldSide / 2}, n);
  }
  return {};
}

}  // namespace edgeland::bench
