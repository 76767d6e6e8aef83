#pragma once
// What `edgeland replay` and `edgeland demo` report about a landscape, in one place.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::cli {

// Landscape::state_hash() as 16 lower-case hex digits.
std::string state_hash_hex(std::uint64_t hash);

// Twice the area of every material whose area is not 0, ascending, empty space (0) included:
// the values sum to twice the world's area. O(materials).
std::vector<std::pair<Material, Int128>> material_areas(const Landscape& landscape);

}  // namespace edgeland::cli
