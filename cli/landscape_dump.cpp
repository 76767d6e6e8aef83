#include "landscape_dump.hpp"

#include <array>

#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::cli {

std::string landscape_dump(const Landscape& landscape) {
  std::array<PolygonSet, kMaterialCount> by_material;
  landscape.polygons_in(landscape.world(), [&](const PolygonView& v) {
    by_material[v.material.value()].push_back(*v.polygon);
    return true;
  });
  std::string out;
  for (std::size_t m = 1; m < kMaterialCount; ++m) {
    if (by_material[m].empty()) continue;
    out += std::to_string(m) + '\t' + to_wkt(by_material[m]) + '\n';
  }
  return out;
}

}  // namespace edgeland::cli
