#include "landscape_report.hpp"

#include "log_text.hpp"

namespace edgeland::cli {

std::string state_hash_hex(std::uint64_t hash) { return log::hex16(hash); }

std::vector<std::pair<Material, Int128>> material_areas(const Landscape& landscape) {
  std::vector<std::pair<Material, Int128>> out;
  for (std::size_t m = 0; m < kMaterialCount; ++m) {
    const auto material = static_cast<Material>(m);
    const Int128 twice = landscape.twice_area(material);
    if (twice != 0) out.emplace_back(material, twice);
  }
  return out;
}

}  // namespace edgeland::cli
