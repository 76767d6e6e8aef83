#include "landscape_workloads.hpp"

#include "landscape_shapes.hpp"
#include "splitmix64.hpp"

namespace edgeland::bench {
namespace {

std::vector<Edit> edits_of(const std::vector<Polygon>& polygons, EditKind kind, Material m) {
  std::vector<Edit> out;
  out.reserve(polygons.size());
  for (ValidSet& shape : as_shapes(polygons)) out.push_back({std::move(shape), kind, m});
  return out;
}

std::vector<Edit> circles(std::uint64_t seed, std::size_t n, EditKind kind, Material m) {
  std::vector<Polygon> polygons;
  for (const Point64& c : random_points(seed, n, kEditWorld)) polygons.push_back(ngon(c, 40, 32));
  return edits_of(polygons, kind, m);
}

std::vector<Edit> strokes(std::size_t n) {
  const std::vector<Point64> walk = random_walk(0xD16'6E2, n, 10.0, inset(kEditWorld, 64));
  std::vector<Polygon> polygons;
  for (std::size_t i = 0; i < n; ++i) polygons.push_back(capsule(walk[i], walk[i + 1], 20, 32));
  return edits_of(polygons, EditKind::kCarve, kEmpty);
}

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
      return circles(0xCA4'F1A6, n, EditKind::kCarve, kEmpty);
    case Workload::kDig:
      return strokes(n);
    case Workload::kFill:
      return circles(0xF111'0002, n, EditKind::kFill, 2);
    case Workload::kSpot:
      return spot(n);
  }
  return {};
}

}  // namespace edgeland::bench
