#include "landscape_workloads.hpp"

#include "landscape_shapes.hpp"
#include "splitmix64.hpp"

namespace edgeland::bench {
namespace {

std::vector<Edit> spot(std::size_t n) {
  SplitMix64 random(0x5907);
  const Point64 centre{kEditWorldSide / 2, kEditWorldSide / 2};
  std::vector<Edit> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 c{centre.x - 8 + static_cast<std::int64_t>(random.next() % 17),
                    centre.y - 8 + static_cast<std::int64_t>(random.next() % 17)};
    const double radius = 3.0 + 197.0 * random.unit();
    const std::size_t sides = 16 + random.next() % 33;
    const bool fill = random.next() % 4 == 0;
    out.push_back({ValidSet(PolygonSet{ngon(c, radius, sides)}, Operand::kClip),
                   fill ? EditKind::kFill : EditKind::kCarve, fill ? Material(2) : kEmpty});
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
    case Workload::kSpot:
      return spot(n);
  }
  return {};
}

}  // namespace edgeland::bench
