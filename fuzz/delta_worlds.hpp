#pragma once
// The worlds the delta targets apply their inputs to (delta, net_message): small limits, a
// 1024^2 world edited a little, with regions when asked. Defined in delta_decoders.cpp.
#include <cstdint>
#include <string>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::fuzz {

// Small limits: a hostile PATCH may describe any world these allow, and the fuzzer must stay
// fast.
LandscapeLimits delta_limits();
Polygon square(Point64 c, std::int64_t r);
// A world of 1024^2 filled and edited a little; with regions (depth 2, ids per region) when asked.
Landscape edited_world(bool regions);
// A delta's bytes with their checksum made right: mutations then reach the payload instead of
// stopping at the checksum.
void fix_checksum(std::string& bytes);

}  // namespace edgeland::fuzz
